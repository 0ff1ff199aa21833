#version 450 core
// A list of indirect draws (DrawElementsIndirectCommand, 5 uints) of the GPU sampler's polygon
// plants, copied for the adjacency index lists (GL_TRIANGLES_ADJACENCY), which hold six indices a
// triangle where the triangle lists hold three: each draw's index count and first index doubled.
// The list keeps its count of draws, which no draw past it may exceed.
layout(local_size_x = 64) in;

layout(std430, binding = 41) readonly buffer Commands { uint commands[]; };
layout(std430, binding = 42) writeonly buffer Adjacent { uint adjacent[]; };
layout(std430, binding = 43) readonly buffer DrawCounts { uint draw_counts[]; };
uniform uint first_command, command_count;
uniform uint count_slot;  // the list's count of draws in draw_counts

void main() {
  uint c = gl_GlobalInvocationID.x;
  if (c >= min(command_count, draw_counts[count_slot])) return;
  uint from = 5u * (first_command + c), to = 5u * c;
  adjacent[to] = 2u * commands[from];            // index count
  adjacent[to + 1u] = commands[from + 1u];       // instances
  adjacent[to + 2u] = 2u * commands[from + 2u];  // first index
  adjacent[to + 3u] = commands[from + 3u];       // base vertex
  adjacent[to + 4u] = commands[from + 4u];       // base instance: the plant list's place
}
