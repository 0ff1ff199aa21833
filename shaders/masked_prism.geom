#version 450 core
// The whole shadow volume of each triangle an alpha mask may cut (mask_cut.glsl): caps and all
// three sides, a closed convex prism (a frustum for a point light) reaching to infinity away from
// the light. Drawn without depth test, its faces cover every pixel whose surface the triangle may
// shadow; masked_prism.frag decides there, with the triangle and its mask handed on.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;

in vec3 world_position[];
in vec4 vertex_surface[];

uniform mat4 view_projection;
#include "light_facing.glsl"
#include "mask_cut.glsl"

flat out vec3 corners[3];
flat out vec2 corner_uvs[3];
flat out vec2 material;  // surface_texture.glsl's code and alpha threshold

void volume_vertex(vec4 position) {
  gl_Position = position;
  for (int i = 0; i < 3; ++i) {
    corners[i] = world_position[2 * i];
    corner_uvs[i] = vertex_surface[2 * i].xy;
  }
  material = vertex_surface[0].zw;
  EmitVertex();
}
#include "volume_faces.glsl"

void main() {
  if (!cut_by_mask(vertex_surface[0].zw)) return;
  vec3 p[3] = vec3[3](world_position[0], world_position[2], world_position[4]);
  float f = facing(p[0], p[1], p[2]);
  if (!(abs(f) > 0.0)) return;  // edge-on to the light (or degenerate): casts no area
  bool sides[3] = bool[3](true, true, true);
  volume_faces(p, f, true, sides);
}
