#version 450 core
// Pass 1 of point splatting: the nearest depth per pixel. With KEEP_PROJECTION (the frame's) it
// also keeps where each point went, for pass 2.
#include "point_common.glsl"
#define VISIT(pixel, depth, point) atomicMin(depths[pixel], depth)
#ifdef KEEP_PROJECTION
#define PROJECTED(point, corner, depth) \
  projected[point] = uvec2((uint(corner.x) & 0xFFFFu) | (uint(corner.y) << 16), depth)
#define OUTSIDE(point) projected[point] = uvec2(0u, no_point)
#endif
#include "point_walk.glsl"
