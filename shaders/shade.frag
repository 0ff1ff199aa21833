#version 450 core
// The frame's last pass: lights the surface each pixel holds (surface.frag, point_surface.frag).
// Pixels without one keep the sky the targets were cleared to.
layout(binding = 2) uniform sampler2D surface_normals;
layout(binding = 3) uniform sampler2D surface_albedos;
layout(binding = 4) uniform sampler2D surface_depths;  // linear view depth, negative for none
uniform mat4 pixel_to_world;  // inverse of view_projection
uniform vec3 camera_forward;

layout(location = 0) out vec4 out_color;       // sRGB
layout(location = 1) out float out_visibility;  // the `shadow` AOV
layout(location = 2) out float out_aliasing;    // the `aliasing` AOV

#include "lighting.glsl"

// The point at linear view depth `depth` on the ray through the pixel's centre, as
// app/render/pixel_rays.hpp finds it for the exact reference.
vec3 surface_position(vec2 pixel_centre, float depth) {
  vec2 ndc = pixel_centre / frame_size * 2.0 - 1.0;
  vec4 far_point = pixel_to_world * vec4(ndc, 1.0, 1.0);
  vec3 d = normalize(far_point.xyz / far_point.w - camera_position);
  return camera_position + d * (depth / dot(d, camera_forward));
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(surface_depths, pixel, 0).r;
  if (depth < 0.0) discard;
  vec3 position = surface_position(gl_FragCoord.xy, depth);
  vec3 n = texelFetch(surface_normals, pixel, 0).xyz;
  Shading s = shade(position, n, texelFetch(surface_albedos, pixel, 0).rgb);
  out_color = vec4(linear_to_srgb(s.color), 1.0);
  out_visibility = s.visibility;
  out_aliasing = aliasing_factor(position, n);
}
