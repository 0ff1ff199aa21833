#version 450 core
// Pass 1 of point splatting: the nearest depth per pixel. With KEEP_PROJECTION (the frame's) it
// also keeps where each point went, for pass 2, and adds the image area each point stands for
// (point_coverage.glsl).
#include "point_common.glsl"
#define VISIT(pixel, depth, point) atomicMin(depths[pixel], depth)
#ifdef KEEP_PROJECTION
#include "point_coverage.glsl"
#define PROJECTED(point, draw, world, ndc, corner, depth)                                 \
  projected[point] = uvec2((uint(corner.x) & 0xFFFFu) | (uint(corner.y) << 16), depth); \
  add_coverage(point, draw, world, ndc, corner, depth)
#define OUTSIDE(point) projected[point] = uvec2(0u, no_point)
#endif
#include "point_walk.glsl"
