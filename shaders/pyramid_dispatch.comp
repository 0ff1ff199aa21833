#version 450 core
// The depth pyramid's build commands for glDispatchComputeIndirect, in two passes. LIST, a thread
// a tile: the changed tiles (with whole_image, every tile) into changed_list, their flags cleared
// for the next build. Then one thread: the base pass takes a work group per listed tile; the levels
// above it are built whole, or not at all where no tile changed. Not one thread walking every tile:
// on a GPU its reads come one after another, 13 builds a frame.
#define LISTS_CHANGES
#include "depth_pyramid.glsl"

// commands[p] the groups of pass p; commands[pass_count].x the tiles listed so far.
layout(std430, binding = 30) buffer Commands { uvec4 commands[]; };
uniform uint pass_count;

#ifdef LIST
layout(local_size_x = 64) in;
uniform bool whole_image;

void main() {
  ivec2 tiles = tile_counts();
  uint t = gl_GlobalInvocationID.x;
  if (t >= uint(tiles.x * tiles.y) || (!whole_image && changed_tiles[t] == 0u)) return;
  changed_list[atomicAdd(commands[pass_count].x, 1u)] = t;
  changed_tiles[t] = 0u;
}
#else
layout(local_size_x = 1) in;
layout(std430, binding = 29) readonly buffer Whole { uvec4 whole[]; };  // each pass's groups, built

void main() {
  uint listed = commands[pass_count].x;
  commands[pass_count].x = 0u;
  commands[0] = uvec4(listed, 1u, 1u, 0u);
  for (uint p = 1u; p < pass_count; ++p) commands[p] = listed > 0u ? whole[p] : uvec4(0u, 1u, 1u, 0u);
}
#endif
