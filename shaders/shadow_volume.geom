#version 450 core
// Shadow volumes from silhouette edges (Crow 1977; counted as Heidmann 1991 and Everitt and
// Kilgard 2002 describe): each triangle, turned to face the light, is the near cap of its volume;
// its projection away from the light at infinity the far cap (z-fail only); and a quad along each
// of its edges whose neighbour faces the light the other way, (N1·L)(N2·L) < 0 with the two
// normals oriented alike, or that has no neighbour. Between two triangles that face the light
// alike the two quads would cancel, so neither is drawn; on a closed mesh's silhouette both are,
// and the count inside is 2. Open and two-sided meshes (leaves, planes) cast correctly this way.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;

in vec3 world_position[];

uniform mat4 view_projection;
#include "light_facing.glsl"
// z-fail counting needs the far caps; z-pass counting does without.
uniform bool far_caps;

vec4 near_vertex(vec3 p) { return view_projection * vec4(p, 1.0); }
// The point at infinity in the direction from the light through p.
vec4 far_vertex(vec3 p) { return view_projection * vec4(light.w * p - light.xyz, 0.0); }

void emit(vec4 a, vec4 b, vec4 c) {
  gl_Position = a; EmitVertex();
  gl_Position = b; EmitVertex();
  gl_Position = c; EmitVertex();
  EndPrimitive();
}

void main() {
  vec3 p[3] = vec3[3](world_position[0], world_position[2], world_position[4]);
  vec3 across[3] = vec3[3](world_position[1], world_position[3], world_position[5]);
  float f = facing(p[0], p[1], p[2]);
  if (!(abs(f) > 0.0)) return;  // edge-on to the light (or degenerate): casts no area
  bool lit_side = f > 0.0;      // wound to face the light as given
  if (lit_side) emit(near_vertex(p[0]), near_vertex(p[1]), near_vertex(p[2]));
  else emit(near_vertex(p[0]), near_vertex(p[2]), near_vertex(p[1]));
  if (far_caps) {
    if (lit_side) emit(far_vertex(p[0]), far_vertex(p[2]), far_vertex(p[1]));
    else emit(far_vertex(p[0]), far_vertex(p[1]), far_vertex(p[2]));
  }
  for (int i = 0; i < 3; ++i) {
    vec3 a = p[i], b = p[(i + 1) % 3];
    // The neighbour (b, a, across), wound like this triangle across their edge.
    if (f * facing(b, a, across[i]) > 0.0) continue;
    if (!lit_side) { vec3 t = a; a = b; b = t; }
    // Facing out, the quad of edge a -> b runs a, a at infinity, b, b at infinity.
    gl_Position = near_vertex(a); EmitVertex();
    gl_Position = far_vertex(a); EmitVertex();
    gl_Position = near_vertex(b); EmitVertex();
    gl_Position = far_vertex(b); EmitVertex();
    EndPrimitive();
  }
}
