// Which way a triangle faces the light, for the stages that find silhouette edges from edge
// adjacency (shadow_volume.geom, silhouette_edges.geom): an edge is on the silhouette where its two
// triangles, wound alike across it, face the light in opposite ways, (N1·L)(N2·L) < 0.

// Homogeneous: (position, 1) for point and spot lights, (-direction, 0) for directional ones.
uniform vec4 light;

bool before(vec3 u, vec3 v) { return u.x != v.x ? u.x < v.x : u.y != v.y ? u.y < v.y : u.z < v.z; }

// How triangle (a, b, c) faces the light, with the sign of this order of its vertices. Computed
// from its vertices in one fixed order, so that a triangle and its neighbour agree bit for bit on
// which way each faces: a disagreement would leave a gap in a volume or a silhouette.
float facing(vec3 a, vec3 b, vec3 c) {
  float order = 1.0;
  vec3 t;
  if (before(b, a)) { t = a; a = b; b = t; order = -order; }
  if (before(c, b)) { t = b; b = c; c = t; order = -order; }
  if (before(b, a)) { t = a; a = b; b = t; order = -order; }
  return order * dot(cross(b - a, c - a), light.xyz - light.w * a);
}
