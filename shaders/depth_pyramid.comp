#version 450 core
// Builds the farthest-depth pyramid (depth_pyramid.glsl). With BASE, levels 0 to 2 from the
// polygons' depth and the points' nearest depths, a block of 4 × 4 pixels a thread: level 0 is
// the nearest depth within a pixel of each pixel, so that one-pixel gaps between leaves and
// between point splats hide what lies behind them (on the ecosystem's default view half the
// points and a quarter of the triangles; docs/benchmarks.md). Otherwise `level` from the one below.
#define PYRAMID_WRITTEN
#ifdef BASE
#define READS_CHANGES
#endif
#include "depth_pyramid.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

#ifdef BASE
layout(std430, binding = 6) readonly buffer PointDepths { uint point_depths[]; };
uniform sampler2D polygon_depth;

float nearest_at(ivec2 pixel) {
  pixel = clamp(pixel, ivec2(0), pyramid_size[0] - 1);
  float nearest = texelFetch(polygon_depth, pixel, 0).r;
  uint point = point_depths[uint(pixel.y * pyramid_size[0].x + pixel.x)];
  return point != 0xFFFFFFFFu ? min(nearest, uintBitsToFloat(point)) : nearest;
}

void store(int level, ivec2 texel, float depth) {
  if (all(lessThan(texel, pyramid_size[level]))) pyramid[pyramid_index(level, texel)] = depth;
}

// A work group per changed tile (changed_list), its 32 × 32 pixels and a pixel around them read
// once for all of its threads:
// a thread reading its own 6 × 6 read each pixel 2.25 times on average (on llvmpipe the base pass
// of a 960 × 540 build took 5.6 ms that way, 5.1 ms this way).
const int group_pixels = tile_pixels, tile_side = group_pixels + 2;
shared float tile[tile_side][tile_side];

void main() {
  uint number = changed_list[gl_WorkGroupID.x];
  ivec2 group_tile = ivec2(int(number) % tile_counts().x, int(number) / tile_counts().x);
  ivec2 tile_origin = group_tile * group_pixels - 1;
  for (uint i = gl_LocalInvocationIndex; i < uint(tile_side * tile_side); i += gl_WorkGroupSize.x * gl_WorkGroupSize.y) {
    ivec2 at = ivec2(int(i) % tile_side, int(i) / tile_side);
    tile[at.y][at.x] = nearest_at(tile_origin + at);
  }
  barrier();
  ivec2 block = group_tile * ivec2(gl_WorkGroupSize.xy) + ivec2(gl_LocalInvocationID.xy);
  ivec2 origin = block * 4;
  if (any(greaterThanEqual(origin, pyramid_size[0]))) return;
  // The 6 × 6 pixels around the block, their nearest within a pixel each way: rows first.
  ivec2 corner = ivec2(gl_LocalInvocationID.xy) * 4;  // the block's pixel left of and below it, in the tile
  float rows[6][4];
  for (int y = 0; y < 6; ++y) {
    float around[6];
    for (int x = 0; x < 6; ++x) around[x] = tile[corner.y + y][corner.x + x];
    for (int x = 0; x < 4; ++x) rows[y][x] = min(around[x], min(around[x + 1], around[x + 2]));
  }
  float farthest_1[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      float depth = min(rows[y][x], min(rows[y + 1][x], rows[y + 2][x]));
      ivec2 pixel = origin + ivec2(x, y);
      store(0, pixel, depth);
      // A pixel past the image's edge takes its last pixels' depths: at worst a farther one.
      farthest_1[y / 2][x / 2] = max(farthest_1[y / 2][x / 2], depth);
    }
  }
  float farthest_2 = 0.0;
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 2; ++x) {
      store(1, block * 2 + ivec2(x, y), farthest_1[y][x]);
      farthest_2 = max(farthest_2, farthest_1[y][x]);
    }
  }
  store(2, block, farthest_2);
}
#else
uniform int level;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, pyramid_size[level]))) return;
  ivec2 below = pyramid_size[level - 1];
  float farthest = 0.0;
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 2; ++x) {
      ivec2 child = 2 * texel + ivec2(x, y);
      if (all(lessThan(child, below))) farthest = max(farthest, pyramid_at(level - 1, child));
    }
  }
  pyramid[pyramid_index(level, texel)] = farthest;
}
#endif
