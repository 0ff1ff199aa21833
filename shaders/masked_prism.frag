#version 450 core
// Where an alpha-masked triangle shadows the frame's surface: the ray from the surface toward the
// light meets the triangle (Möller and Trumbore 1997) where its mask keeps it. As the ray-traced
// reference does, the ray starts a share of the eye's distance off the surface on its seen side,
// and the mask is read on the texture's full-size level. Writes 0 (shadowed) into the light mask.
#include "frame_surface.glsl"
#include "surface_texture.glsl"
uniform vec4 light;  // light_facing.glsl's homogeneous light
uniform vec3 camera_position;
uniform vec2 frame_size;
#include "surface_position.glsl"

flat in vec3 corners[3];
flat in vec2 corner_uvs[3];
flat in float corner_scales[3];
flat in float code;
layout(location = 0) out float lit;

const float origin_offset = 2e-4;  // app/reference/exact_visibility.cpp's
// How far outside the triangle a ray may pass and still meet it, in barycentric terms: two
// triangles sharing an edge both miss a ray along it only by rounding.
const float edge_slack = 1e-5;

void main() {
  Surface surface = frame_surface(ivec2(gl_FragCoord.xy));
  if (!(surface.depth >= 0.0)) discard;
  vec3 s = surface_position(gl_FragCoord.xy, surface.depth);
  s += surface.normal * (origin_offset * distance(s, camera_position));
  vec3 to_light = light.xyz - light.w * s;  // reaches the light at t = 1 for a point light
  vec3 e1 = corners[1] - corners[0], e2 = corners[2] - corners[0];
  vec3 q = cross(to_light, e2);
  float det = dot(e1, q);
  if (det == 0.0) discard;
  vec3 o = s - corners[0];
  float u = dot(o, q) / det;
  vec3 r = cross(o, e1);
  float v = dot(to_light, r) / det;
  float t = dot(e2, r) / det;
  if (u < -edge_slack || v < -edge_slack || u + v > 1.0 + edge_slack) discard;
  if (!(t > 0.0) || (light.w > 0.0 && !(t < 1.0))) discard;
  vec3 weights = vec3(1.0 - u - v, u, v);
  vec2 uv = weights.x * corner_uvs[0] + weights.y * corner_uvs[1] + weights.z * corner_uvs[2];
  float keep_scale = fragment_keep_scale(corner_scales[0], dot(weights, vec3(corner_scales[0], corner_scales[1], corner_scales[2])));
  if (masked_away(surface_texel_grad(uv, code, vec2(0.0), vec2(0.0)), keep_scale)) discard;
  lit = 0.0;
}
