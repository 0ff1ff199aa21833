#version 450 core
// One thread: the depth pyramid's build commands for glDispatchComputeIndirect. The base pass
// takes a work group per changed tile (listed in changed_list, their flags cleared for the next
// build; with whole_image, every tile); the levels above it are built whole, or not at all where no
// tile changed.
#define LISTS_CHANGES
#include "depth_pyramid.glsl"
layout(local_size_x = 1) in;

layout(std430, binding = 29) readonly buffer Whole { uvec4 whole[]; };  // each pass's groups, built
layout(std430, binding = 30) writeonly buffer Commands { uvec4 commands[]; };
uniform uint pass_count;
uniform bool whole_image;

void main() {
  ivec2 tiles = tile_counts();
  uint changed = 0u;
  for (uint t = 0u; t < uint(tiles.x * tiles.y); ++t) {
    if (!whole_image && changed_tiles[t] == 0u) continue;
    changed_list[changed++] = t;
    changed_tiles[t] = 0u;
  }
  commands[0] = uvec4(changed, 1u, 1u, 0u);
  for (uint p = 1u; p < pass_count; ++p) commands[p] = changed > 0u ? whole[p] : uvec4(0u, 1u, 1u, 0u);
}
