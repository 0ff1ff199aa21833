#version 450 core
// A list of indirect draws (DrawElementsIndirectCommand, 5 uints) with the empty ones left out, the
// others in their order, and their number, for glMultiDrawElementsIndirectCount, with the
// triangles they draw (for --stats, read back instead of the lists; with adds_triangles added to
// the slot's, where several lists drawn in turn share one copy): one work group,
// a run of draws a thread. The GPU sampler's lists hold a draw per table and part lane, most of
// them empty (82 tables × 65 lanes a distance band on the ecosystem), and a driver walks every
// draw it is given.
#include "group_scan.glsl"
layout(local_size_x = 256) in;

layout(std430, binding = 41) readonly buffer Commands { uint commands[]; };
layout(std430, binding = 42) writeonly buffer Drawn { uint drawn[]; };
layout(std430, binding = 43) buffer DrawnCounts { uvec2 drawn_counts[]; };  // draws, triangles
uniform uint first_command, command_count;
uniform bool adds_triangles;
uniform uint drawn_first;  // the copy's first place in drawn
uniform uint count_slot;   // its place in drawn_counts

bool draws_something(uint c) { return commands[5u * c] > 0u && commands[5u * c + 1u] > 0u; }

void main() {
  uint run = (command_count + 255u) / 256u;
  uint first = first_command + min(gl_LocalInvocationID.x * run, command_count);
  uint end = first_command + min(gl_LocalInvocationID.x * run + run, command_count);
  uint own = 0u, own_triangles = 0u;
  for (uint c = first; c < end; ++c) {
    own += draws_something(c) ? 1u : 0u;
    own_triangles += commands[5u * c] / 3u * commands[5u * c + 1u];
  }
  uint total, triangles;
  uint at = drawn_first + inclusive_sum(own, total) - own;
  inclusive_sum(own_triangles, triangles);
  for (uint c = first; c < end; ++c) {
    if (!draws_something(c)) continue;
    for (uint i = 0u; i < 5u; ++i) drawn[5u * at + i] = commands[5u * c + i];
    ++at;
  }
  if (gl_LocalInvocationID.x == 0u) drawn_counts[count_slot] = uvec2(total, triangles + (adds_triangles ? drawn_counts[count_slot].y : 0u));
}
