#version 450 core
// Pass 1 of point splatting: the nearest depth per pixel. With KEEP_PROJECTION (the frame's) it
// also keeps where each point went and, of the points in front of the polygons drawn so far, the
// nearest depth of those whose centre falls in each pixel, for pass 2, and the image area each
// stands for (point_coverage.glsl).
#include "point_common.glsl"
#define VISIT(pixel, depth, point) atomicMin(depths[pixel], depth)
#ifdef KEEP_PROJECTION
#include "point_coverage.glsl"
void keep_projection(uint p, uvec4 d, vec3 world, vec2 ndc, ivec2 corner, uint depth);  // below
#define PROJECTED(point, draw, world, ndc, corner, depth) keep_projection(point, draw, world, ndc, corner, depth)
#define OUTSIDE(point) projected[point] = uvec2(0u, no_point)
#endif
#include "point_walk.glsl"

#ifdef KEEP_PROJECTION
void keep_projection(uint p, uvec4 d, vec3 world, vec2 ndc, ivec2 corner, uint depth) {
  ivec2 centre = min(ivec2((ndc * 0.5 + 0.5) * vec2(target_size)), target_size - 1);
  projected[p] = uvec2(pack_splat(corner, centre, splat_size), depth);
  if (!in_front_of_polygons(centre, depth)) return;
  atomicMin(centre_depths[centre.y * target_size.x + centre.x], depth);
  add_coverage(p, d, world, corner);
}
#endif
