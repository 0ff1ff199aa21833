#version 450 core
// Marks, in level 0 of a max pyramid over a shadow view's image (depth_pyramid.glsl), the texels
// where the frame shows a surface: the farthest of their window depths in that view there (above
// 0: depth grows along the light's rays in every map, shadow/light_projection.hpp), 0 elsewhere;
// with CLEAR `mark` everywhere: 0 before the marks, or 1, a receiver at the far end of every texel
// (DepthPyramid::mark_everywhere). The frame's surfaces are its nearest window depths, level 0 of the
// frame's own depth pyramid (binding 25).
// Of a cascade, only the surfaces that look it up: none inside an earlier cascade's square
// (shadow_views.glsl, FIRST_CONTAINING).
#define PYRAMID_WRITTEN
#include "depth_pyramid.glsl"
// The same level 0 as float bits, which order as the floats do where those are not negative: the
// farthest mark is kept whichever thread writes last.
layout(std430, binding = 17) buffer PyramidBits { uint pyramid_bits[]; };
layout(local_size_x = 8, local_size_y = 8) in;

#ifdef CLEAR
uniform float mark;
void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(texel, pyramid_size[0]))) pyramid[pyramid_index(0, texel)] = mark;
}
#else
layout(std430, binding = 25) readonly buffer FrameDepths { float frame_depths[]; };  // the frame's level 0
uniform ivec2 frame_size;
uniform int pixel_step;         // every this many pixels each way
uniform mat4 frame_to_world;    // inverse of the frame's view-projection
uniform mat4 map_view_projection;
uniform mat4 earlier_views[8];  // world → clip of the cascades before this one
uniform int earlier_count;
uniform float map_texels;  // texels per side of the cascades' maps

#include "cascade_square.glsl"

bool in_earlier_view(vec3 p) {
  for (int i = 0; i < earlier_count; ++i) {
    if (in_cascade_square(earlier_views[i], p, map_texels)) return true;
  }
  return false;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * pixel_step;
  if (any(greaterThanEqual(pixel, frame_size))) return;
  float depth = frame_depths[pixel.y * frame_size.x + pixel.x];
  if (!(depth < 1.0)) return;  // nothing drawn there
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(frame_size) * 2.0 - 1.0;
  vec4 world = frame_to_world * vec4(ndc, depth * 2.0 - 1.0, 1.0);
  vec3 position = world.xyz / world.w;
  if (in_earlier_view(position)) return;
  vec4 clip = map_view_projection * vec4(position, 1.0);
  if (!(clip.w > 0.0)) return;
  vec2 map = clip.xy / clip.w;
  if (any(greaterThan(abs(map), vec2(1.0)))) return;
  ivec2 texel = min(ivec2((map * 0.5 + 0.5) * vec2(pyramid_size[0])), pyramid_size[0] - 1);
  float map_depth = max(clip.z / clip.w * 0.5 + 0.5, 1e-6);  // a mark is above 0
  atomicMax(pyramid_bits[pyramid_offset[0] + uint(texel.y * pyramid_size[0].x + texel.x)], floatBitsToUint(map_depth));
}
#endif
