#version 450 core
// --method adaptive: the pages the frame's lighting will look up (lighting.glsl,
// paged_shadow_test), from the surfaces each pixel holds that face the light: listed once each,
// for the host to give them layers and draw them before the lighting.
layout(local_size_x = 8, local_size_y = 8) in;
#include "frame_surface.glsl"
#include "shadow_views.glsl"
#include "surface_position.glsl"

layout(std430, binding = 27) buffer PageFlags { uint page_flags[]; };  // 1 once a slot is listed
layout(std430, binding = 28) buffer PageList {
  uint requested_count;
  uint requested[];  // the pages' slots (page_slot)
};

void request(ivec2 pixel, float depth, vec3 n) {
  vec3 position = surface_position(vec2(pixel) + 0.5, depth);
  vec3 to_light = direction_to_light(position);
  float n_dot_l = dot(n, to_light);
  if (n_dot_l <= 0.0) return;  // unlit, whatever the map holds
  if (light_type == SPOT && dot(-to_light, light_direction) < spot_cos_cone) return;
  int view = shadow_view(position);
  int level = wanted_level(view, position);
  vec4 clip = shadow_matrices[view] * vec4(page_lookup_position(view, level, position, n, n_dot_l), 1.0);
  if (clip.w <= 0.0) return;
  vec2 ndc = clip.xy / clip.w;
  if (any(greaterThan(abs(ndc), vec2(1.0)))) return;
  level = addressed_level(view, ndc, level);
  uint id = page_slot(view, level, page_at(ndc, level));
  if (page_flags[id] == 0u && atomicExchange(page_flags[id], 1u) == 0u) requested[atomicAdd(requested_count, 1u)] = id;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(frame_size)))) return;
  Surface surface = frame_surface(pixel);
  if (surface.depth < 0.0) return;
  request(pixel, surface.depth, surface.normal);
  // Points covering part of the pixel: the lighting shades the polygons behind them too.
  if (surface.albedo.a < 1.0) {
    float depth = texelFetch(polygon_depths, pixel, 0).r;
    if (depth >= 0.0) request(pixel, depth, texelFetch(polygon_normals, pixel, 0).xyz);
  }
}
