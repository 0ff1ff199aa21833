// A farthest-depth pyramid over the frame (app/render/depth_pyramid.hpp): window depths, level 0
// per pixel (the nearest within a pixel of it), each level above the farthest of the 2 × 2 below;
// levels packed one after another.
uniform uint pyramid_offset[16];
uniform ivec2 pyramid_size[16];
uniform int pyramid_levels;

uint pyramid_index(int level, ivec2 texel) { return pyramid_offset[level] + uint(texel.y * pyramid_size[level].x + texel.x); }
#ifdef PYRAMID_WRITTEN
layout(std430, binding = 17) buffer Pyramid { float pyramid[]; };
float pyramid_at(int level, ivec2 texel) { return pyramid[pyramid_index(level, texel)]; }
#else
// Its readers fetch it as R32F texels of a buffer texture over the same store: llvmpipe loads
// shader storage lane by lane (plant_instances.glsl), and a hidden plant's test reads up to 256.
layout(binding = 14) uniform samplerBuffer pyramid_texels;
float pyramid_at(int level, ivec2 texel) { return texelFetch(pyramid_texels, int(pyramid_index(level, texel))).r; }
#endif

// Whether every texel of `level` over the pixels from `lo` to `hi` (level 0's) lies nearer than
// `depth` (with `or_at`, or at it), read up to the first that does not.
bool all_nearer_at(int level, ivec2 lo, ivec2 hi, float depth, bool or_at) {
  ivec2 a = lo >> level, b = hi >> level;
  for (int y = a.y; y <= b.y; ++y) {
    for (int x = a.x; x <= b.x; ++x) {
      float drawn = pyramid_at(level, ivec2(x, y));
      if (drawn > depth || (drawn == depth && !or_at)) return false;
    }
  }
  return true;
}

// Whether every depth drawn over the pixels from `lo` to `hi` (inclusive, level 0's) lies nearer
// than `depth` (with `or_at`, or at it): the answer of the lowest level where they span at most
// 16 × 16 texels. A coarser level's texels reach further past the rectangle, into gaps that show
// the sky: at most 4 × 4 drew 1.8 times the triangles on a dense stand of 10^5 plants and 1.15
// times on the ecosystem's default view, and its frames took longer on llvmpipe
// (docs/benchmarks.md); 32 × 32 saves a few percent more. But a texel holds the farthest of those
// below it, so where the lowest level at which they span at most 2 × 2 says "all nearer", so would
// that one: a plant hidden behind a closed canopy is known in four reads instead of up to 256.
bool all_nearer(ivec2 lo, ivec2 hi, float depth, bool or_at) {
  lo = clamp(lo, ivec2(0), pyramid_size[0] - 1);
  hi = clamp(hi, ivec2(0), pyramid_size[0] - 1);
  int level = 0;
  while (level + 1 < pyramid_levels && any(greaterThan((hi >> level) - (lo >> level), ivec2(15)))) ++level;
  int coarse = level;
  while (coarse + 1 < pyramid_levels && any(greaterThan((hi >> coarse) - (lo >> coarse), ivec2(1)))) ++coarse;
  if (coarse > level && all_nearer_at(coarse, lo, hi, depth, or_at)) return true;
  return all_nearer_at(level, lo, hi, depth, or_at);
}

// The pyramid's tiles of tile_pixels × tile_pixels pixels, a flag each, rows from the bottom, that
// what was drawn since its last build may have changed (DepthPyramid::build_changed builds only
// those). A pass that draws marks them with MARKS_CHANGES.
const int tile_pixels = 32;
#if defined(MARKS_CHANGES) || defined(LISTS_CHANGES)
layout(std430, binding = 39) buffer ChangedTiles { uint changed_tiles[]; };
#endif
#if defined(LISTS_CHANGES) || defined(READS_CHANGES)
// The changed tiles' numbers in a list (pyramid_dispatch.comp), for the base pass.
layout(std430, binding = 40) buffer ChangedList { uint changed_list[]; };
#endif
ivec2 tile_counts() { return (pyramid_size[0] + tile_pixels - 1) / tile_pixels; }
#ifdef MARKS_CHANGES
// Marks the tiles over level 0's pixels `lo` to `hi` (inclusive) and `margin` pixels around:
// the nearest depth within a pixel (level 0) and a splat about a point reach that far past them.
void mark_changed(ivec2 lo, ivec2 hi, int margin) {
  ivec2 first = clamp(lo - margin, ivec2(0), pyramid_size[0] - 1) / tile_pixels;
  ivec2 last = clamp(hi + margin, ivec2(0), pyramid_size[0] - 1) / tile_pixels;
  int row = tile_counts().x;
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) changed_tiles[y * row + x] = 1u;
  }
}
#endif
