#version 450 core
// The frame's last pass: lights the surface each pixel holds (surface.frag, point_surface.frag).
// Pixels without one keep the sky the targets were cleared to. Where points cover only part of a
// pixel (the albedo's alpha), the rest shows the polygons drawn behind them, or the sky, lit
// likewise and blended in linear light; the `shadow` and `aliasing` AOVs stay the nearest
// surface's.
layout(binding = 2) uniform sampler2D surface_normals;
layout(binding = 3) uniform sampler2D surface_albedos;
layout(binding = 4) uniform sampler2D surface_depths;  // linear view depth, negative for none
// The polygons' surfaces before the points were added.
layout(binding = 5) uniform sampler2D polygon_normals;
layout(binding = 6) uniform sampler2D polygon_albedos;
layout(binding = 7) uniform sampler2D polygon_depths;
uniform vec3 sky;  // linear RGB

layout(location = 0) out vec4 out_color;       // sRGB
layout(location = 1) out float out_visibility;  // the `shadow` AOV
layout(location = 2) out float out_aliasing;    // the `aliasing` AOV

#include "lighting.glsl"
#include "surface_position.glsl"

vec3 polygon_color(ivec2 pixel) {
  float depth = texelFetch(polygon_depths, pixel, 0).r;
  if (depth < 0.0) return sky;
  vec3 position = surface_position(gl_FragCoord.xy, depth);
  return shade(position, texelFetch(polygon_normals, pixel, 0).xyz, texelFetch(polygon_albedos, pixel, 0).rgb).color;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(surface_depths, pixel, 0).r;
  if (depth < 0.0) discard;
  vec3 position = surface_position(gl_FragCoord.xy, depth);
  vec3 n = texelFetch(surface_normals, pixel, 0).xyz;
  vec4 albedo = texelFetch(surface_albedos, pixel, 0);
  Shading s = shade(position, n, albedo.rgb);
  vec3 color = albedo.a < 1.0 ? mix(polygon_color(pixel), s.color, albedo.a) : s.color;
  out_color = vec4(linear_to_srgb(color), 1.0);
  out_visibility = s.visibility;
  out_aliasing = aliasing_factor(position, n);
}
