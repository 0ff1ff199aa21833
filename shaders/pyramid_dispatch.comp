#version 450 core
// One thread: the depth pyramid's build commands for glDispatchComputeIndirect, each level's work
// groups where the flag is set (something was drawn since the last build), none where it is not.
layout(local_size_x = 1) in;

layout(std430, binding = 28) readonly buffer Flags { uint flags[]; };
layout(std430, binding = 29) readonly buffer Whole { uvec4 whole[]; };  // each pass's groups, built
layout(std430, binding = 30) writeonly buffer Commands { uvec4 commands[]; };
uniform uint flag;
uniform uint pass_count;

void main() {
  bool build = flags[flag] != 0u;
  for (uint p = 0u; p < pass_count; ++p) commands[p] = build ? whole[p] : uvec4(0u, 1u, 1u, 0u);
}
