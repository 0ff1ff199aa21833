// The faces of a triangle's shadow volume (Crow 1977), wound to face out of it: the triangle turned
// to face the light is its near cap, its projection away from the light its far cap, and a quad
// runs from each edge to the far cap. Needs view_projection and, before this is included, the
// stage's own volume_vertex(clip position), which emits one vertex, and far_vertex(p), where the
// volume ends on the ray from the light through p.

vec4 near_vertex(vec3 p) { return view_projection * vec4(p, 1.0); }

void volume_triangle(vec4 a, vec4 b, vec4 c) {
  volume_vertex(a);
  volume_vertex(b);
  volume_vertex(c);
  EndPrimitive();
}

// The faces of the volume of triangle p, which faces the light as `f` says (facing(), not 0): its
// near cap, its far cap where `far_caps`, and the quads of the edges `sides` picks (edge i runs
// from p[i] to p[i + 1]).
void volume_faces(vec3 p[3], float f, bool far_caps, bool sides[3]) {
  bool lit_side = f > 0.0;  // wound to face the light as given
  if (lit_side) volume_triangle(near_vertex(p[0]), near_vertex(p[1]), near_vertex(p[2]));
  else volume_triangle(near_vertex(p[0]), near_vertex(p[2]), near_vertex(p[1]));
  if (far_caps) {
    if (lit_side) volume_triangle(far_vertex(p[0]), far_vertex(p[2]), far_vertex(p[1]));
    else volume_triangle(far_vertex(p[0]), far_vertex(p[1]), far_vertex(p[2]));
  }
  for (int i = 0; i < 3; ++i) {
    if (!sides[i]) continue;
    vec3 a = p[i], b = p[(i + 1) % 3];
    if (!lit_side) { vec3 t = a; a = b; b = t; }
    // Facing out, the quad of edge a -> b runs a, a at infinity, b, b at infinity.
    volume_vertex(near_vertex(a));
    volume_vertex(far_vertex(a));
    volume_vertex(near_vertex(b));
    volume_vertex(far_vertex(b));
    EndPrimitive();
  }
}
