// A farthest-depth pyramid over the frame (app/render/depth_pyramid.hpp): window depths, level 0
// per pixel (the nearest within a pixel of it), each level above the farthest of the 2 × 2 below;
// levels packed one after another.
#ifdef PYRAMID_WRITTEN
layout(std430, binding = 17) buffer Pyramid { float pyramid[]; };
#else
layout(std430, binding = 17) readonly buffer Pyramid { float pyramid[]; };
#endif
uniform uint pyramid_offset[16];
uniform ivec2 pyramid_size[16];
uniform int pyramid_levels;

float pyramid_at(int level, ivec2 texel) {
  return pyramid[pyramid_offset[level] + uint(texel.y * pyramid_size[level].x + texel.x)];
}

// Whether every depth drawn over the pixels from `lo` to `hi` (inclusive, level 0's) lies nearer
// than `depth` (with `or_at`, or at it): read at the lowest level where they span at most 16 × 16
// texels, up to the first texel that does not. A coarser level's texels reach further past the
// rectangle, into gaps that show the sky: at most 4 × 4 drew 1.8 times the triangles on a dense
// stand of 10^5 plants and 1.15 times on the ecosystem's default view, and its frames took longer
// on llvmpipe (docs/benchmarks.md); 32 × 32 saves a few percent more.
bool all_nearer(ivec2 lo, ivec2 hi, float depth, bool or_at) {
  lo = clamp(lo, ivec2(0), pyramid_size[0] - 1);
  hi = clamp(hi, ivec2(0), pyramid_size[0] - 1);
  int level = 0;
  while (level + 1 < pyramid_levels && any(greaterThan((hi >> level) - (lo >> level), ivec2(15)))) ++level;
  ivec2 a = lo >> level, b = hi >> level;
  for (int y = a.y; y <= b.y; ++y) {
    for (int x = a.x; x <= b.x; ++x) {
      float drawn = pyramid_at(level, ivec2(x, y));
      if (drawn > depth || (drawn == depth && !or_at)) return false;
    }
  }
  return true;
}
