#version 450 core
// The frame's last pass: lights the surface each pixel holds (surface.frag, point_surface.frag),
// and finds the nearest. Pixels without one show the sky. Where points cover only part of a pixel (the albedo's alpha),
// the rest shows the polygons drawn behind them, or the sky, lit likewise and blended in linear
// light; the `shadow` and `aliasing` AOVs stay the nearest surface's. A compute pass, a thread a
// pixel: as a fullscreen fragment pass the default view's frame took 14–21 % longer on llvmpipe
// (docs/benchmarks.md), and on a GPU it leaves the raster units to the polygons.
layout(local_size_x = 8, local_size_y = 8) in;
#include "frame_surface.glsl"
uniform vec3 sky;  // linear RGB
// The frame's nearest surface (the next frame's PSM starts its near plane there): the least
// linear view depth as float bits (positive floats order like their bits), all ones for none. A
// plain read first: after the first pixels almost none needs the atomic.
layout(std430, binding = 26) buffer Nearest { uint nearest; };

layout(binding = 0, rgba8) uniform writeonly image2D out_color;  // sRGB
layout(binding = 1, r8) uniform writeonly image2D out_visibility;  // the `shadow` AOV
layout(binding = 2, r32f) uniform writeonly image2D out_aliasing;  // the `aliasing` AOV

#include "lighting.glsl"
#include "surface_position.glsl"

vec3 polygon_color(ivec2 pixel) {
  float depth = texelFetch(polygon_depths, pixel, 0).r;
  if (depth < 0.0) return sky;
  vec3 position = surface_position(vec2(pixel) + 0.5, depth);
  return shade(pixel, position, texelFetch(polygon_normals, pixel, 0).xyz, texelFetch(polygon_albedos, pixel, 0).rgb).color;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(frame_size)))) return;
  Surface surface = frame_surface(pixel);
  float depth = surface.depth;
  if (depth < 0.0) {
    imageStore(out_color, pixel, vec4(linear_to_srgb(sky), 1.0));
    imageStore(out_visibility, pixel, vec4(1.0));
    imageStore(out_aliasing, pixel, vec4(-1.0));
    return;
  }
  uint depth_bits = floatBitsToUint(depth);
  if (depth > 0.0 && depth_bits < nearest) atomicMin(nearest, depth_bits);
  vec3 position = surface_position(vec2(pixel) + 0.5, depth);
  vec3 n = surface.normal;
  vec4 albedo = surface.albedo;
  Shading s = shade(pixel, position, n, albedo.rgb);
  vec3 color = albedo.a < 1.0 ? mix(polygon_color(pixel), s.color, albedo.a) : s.color;
  imageStore(out_color, pixel, vec4(linear_to_srgb(color), 1.0));
  imageStore(out_visibility, pixel, vec4(s.visibility));
  imageStore(out_aliasing, pixel, vec4(aliasing_factor(position, n)));
}
