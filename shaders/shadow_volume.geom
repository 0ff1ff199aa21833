#version 450 core
// Per-triangle shadow volumes (Crow 1977): each triangle, turned to face the light,
// becomes a closed prism — itself as the near cap, its projection away from the light at infinity
// as the far cap, and a quad along each edge — every face wound to face out. Open and two-sided
// meshes (leaves, planes) cast correctly this way, at the price of fill.
layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

in vec3 world_position[];

uniform mat4 view_projection;
// Homogeneous: (position, 1) for point and spot lights, (-direction, 0) for directional ones.
uniform vec4 light;

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
  vec3 p[3] = vec3[3](world_position[0], world_position[1], world_position[2]);
  float facing = dot(cross(p[1] - p[0], p[2] - p[0]), light.xyz - light.w * p[0]);
  if (!(abs(facing) > 0.0)) return;  // edge-on to the light (or degenerate): casts no area
  if (facing < 0.0) p = vec3[3](p[0], p[2], p[1]);
  emit(near_vertex(p[0]), near_vertex(p[1]), near_vertex(p[2]));
  emit(far_vertex(p[0]), far_vertex(p[2]), far_vertex(p[1]));
  for (int i = 0; i < 3; ++i) {
    // Facing out, the quad of edge a -> b runs a, a at infinity, b, b at infinity.
    vec3 a = p[i], b = p[(i + 1) % 3];
    gl_Position = near_vertex(a); EmitVertex();
    gl_Position = far_vertex(a); EmitVertex();
    gl_Position = near_vertex(b); EmitVertex();
    gl_Position = far_vertex(b); EmitVertex();
    EndPrimitive();
  }
}
