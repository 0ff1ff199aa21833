#version 450 core
// The whole shadow volume of each triangle an alpha mask may cut (mask_cut.glsl): caps and all
// three sides, a closed convex prism (a frustum for a point light) away from the light. Drawn
// without depth test, its faces cover every pixel whose surface the triangle may shadow;
// masked_prism.frag decides there, with the triangle and its mask handed on. Under a directional
// light the prism ends where the scene's box does, so that its far part covers no pixels in vain;
// from a point light it reaches to infinity.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;

in vec3 world_position[];
in vec4 vertex_surface[];

uniform mat4 view_projection;
#include "light_facing.glsl"
#include "mask_cut.glsl"
uniform vec3 scene_min, scene_max;  // a box around every caster and receiver

flat out vec3 corners[3];
flat out vec2 corner_uvs[3];
flat out float corner_scales[3];  // the mask's keep scales (surface_texture.glsl)
flat out float code;              // surface_texture.glsl's

void volume_vertex(vec4 position) {
  gl_Position = position;
  for (int i = 0; i < 3; ++i) {
    corners[i] = world_position[2 * i];
    corner_uvs[i] = vertex_surface[2 * i].xy;
    corner_scales[i] = vertex_surface[2 * i].w;
  }
  code = vertex_surface[0].z;
  EmitVertex();
}
float reach;  // how far the prism runs along a directional light from each corner; 0: to infinity
vec4 far_vertex(vec3 p) {
  if (reach > 0.0) return view_projection * vec4(p - reach * normalize(light.xyz), 1.0);
  return view_projection * vec4(light.w * p - light.xyz, 0.0);  // from the light through p, at infinity
}
#include "volume_faces.glsl"

// How far along the directional light's way `d` the prism of triangle p must run for every point
// of the triangle to leave the box: a slab's exit distance is affine in the start point, so it is
// largest at a corner, and the box's, the least of its slabs', is at most the least of those.
float reach_out_of_box(vec3 p[3], vec3 d) {
  float reach = 1e30;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) continue;
    float side = d[k] > 0.0 ? scene_max[k] : scene_min[k];
    reach = min(reach, max(max((side - p[0][k]) / d[k], (side - p[1][k]) / d[k]), (side - p[2][k]) / d[k]));
  }
  return max(reach, 0.0);
}

void main() {
  if (!cut_by_mask(vertex_surface[0].zw) && !cut_by_mask(vertex_surface[2].zw) && !cut_by_mask(vertex_surface[4].zw)) return;
  vec3 p[3] = vec3[3](world_position[0], world_position[2], world_position[4]);
  reach = light.w == 0.0 ? reach_out_of_box(p, -normalize(light.xyz)) : 0.0;
  float f = facing(p[0], p[1], p[2]);
  if (!(abs(f) > 0.0)) return;  // edge-on to the light (or degenerate): casts no area
  bool sides[3] = bool[3](true, true, true);
  volume_faces(p, f, true, sides);
}
