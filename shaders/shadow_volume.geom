#version 450 core
// Shadow volumes from silhouette edges (Crow 1977; counted as Heidmann 1991 and Everitt and
// Kilgard 2002 describe): each triangle's near cap, its far cap (z-fail only), and a quad along
// each of its edges whose neighbour faces the light the other way, (N1·L)(N2·L) < 0 with the two
// normals oriented alike, or that has no neighbour (volume_faces.glsl). Between two triangles that
// face the light alike the two quads would cancel, so neither is drawn; on a closed mesh's
// silhouette both are, and the count inside is 2. Open and two-sided meshes (leaves, planes) cast
// correctly this way. A triangle an alpha mask may cut casts no volume here, since a count cannot
// follow a texture: masked_prism.geom shadows with it instead, and its neighbours count their
// shared edge as a border.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;

in vec3 world_position[];

uniform mat4 view_projection;
#include "light_facing.glsl"
// z-fail counting needs the far caps; z-pass counting does without.
uniform bool far_caps;

void volume_vertex(vec4 position) {
  gl_Position = position;
  EmitVertex();
}
// The point at infinity in the direction from the light through p.
vec4 far_vertex(vec3 p) { return view_projection * vec4(light.w * p - light.xyz, 0.0); }
#include "volume_faces.glsl"

#ifdef SURFACE_TEXTURES
#include "mask_cut.glsl"
in vec4 vertex_surface[];
bool masked(int v) { return cut_by_mask(vertex_surface[v].zw); }
#else
bool masked(int v) { return false; }
#endif

void main() {
  if (masked(0) || masked(2) || masked(4)) return;
  vec3 p[3] = vec3[3](world_position[0], world_position[2], world_position[4]);
  vec3 across[3] = vec3[3](world_position[1], world_position[3], world_position[5]);
  float f = facing(p[0], p[1], p[2]);
  if (!(abs(f) > 0.0)) return;  // edge-on to the light (or degenerate): casts no area
  bool sides[3];
  // The neighbour (b, a, across), wound like this triangle across their edge.
  for (int i = 0; i < 3; ++i) sides[i] = masked(2 * i + 1) || !(f * facing(p[(i + 1) % 3], p[i], across[i]) > 0.0);
  volume_faces(p, f, far_caps, sides);
}
