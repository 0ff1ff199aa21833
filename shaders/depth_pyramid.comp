#version 450 core
// Builds a level of the farthest-depth pyramid (depth_pyramid.glsl): with BASE level 0 from the
// polygons' depth and the points' nearest depths, otherwise `level` from the one below.
#define PYRAMID_WRITTEN
#include "depth_pyramid.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

#ifdef BASE
layout(std430, binding = 6) readonly buffer PointDepths { uint point_depths[]; };
uniform sampler2D polygon_depth;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, pyramid_size[0]))) return;
  uint index = uint(texel.y * pyramid_size[0].x + texel.x);
  float nearest = texelFetch(polygon_depth, texel, 0).r;
  uint point = point_depths[index];
  if (point != 0xFFFFFFFFu) nearest = min(nearest, uintBitsToFloat(point));
  pyramid[pyramid_offset[0] + index] = nearest;
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
  pyramid[pyramid_offset[level] + uint(texel.y * pyramid_size[level].x + texel.x)] = farthest;
}
#endif
