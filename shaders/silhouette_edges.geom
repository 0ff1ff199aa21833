#version 450 core
// The silhouette edges of a view's casters as the light sees them (Sen, Cammarano and Hanrahan
// 2003), each drawn as a quad over every cell of the silhouette map it crosses. The map's cells
// lie half a texel off the depth map's texels, so that a cell's corners are four depth samples;
// cell (i, j) spans the window coordinates [i, i + 1] x [j, j + 1] of this pass. The quad runs
// past the edge's ends and sides by more than half a cell's diagonal: every cell the edge crosses
// has its centre inside, and silhouette_point.frag finds where in the cell the edge runs.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 12) out;

in vec3 world_position[];

uniform mat4 light_view_projection;
uniform float map_size;  // texels, and cells, per side
#include "light_facing.glsl"

// The edge in cell coordinates, and its ends' window depths.
flat out vec2 edge_start, edge_end;
flat out float start_depth, end_depth;

const float reach = 0.75;  // cells, more than sqrt(2) / 2

// Cuts the segment a -> b in clip space to the near and far planes (-w <= z <= w), as the
// rasterizer cuts the triangles of the depth map. False where nothing is left.
bool clip_depth(inout vec4 a, inout vec4 b) {
  for (int side = 0; side < 2; ++side) {
    float sign = side == 0 ? 1.0 : -1.0;
    float da = a.w + sign * a.z, db = b.w + sign * b.z;  // >= 0 inside
    if (da < 0.0 && db < 0.0) return false;
    if (da < 0.0) a = mix(a, b, da / (da - db));
    else if (db < 0.0) b = mix(a, b, da / (da - db));
  }
  return a.w > 0.0 && b.w > 0.0;
}

vec4 window_vertex(vec2 cell, float depth) { return vec4(cell / map_size * 2.0 - 1.0, depth, 1.0); }

void emit_edge(vec3 a, vec3 b) {
  vec4 ca = light_view_projection * vec4(a, 1.0), cb = light_view_projection * vec4(b, 1.0);
  if (!clip_depth(ca, cb)) return;
  vec3 na = ca.xyz / ca.w, nb = cb.xyz / cb.w;
  // Window coordinates shifted by half a texel: the depth texel centres fall on cell corners.
  vec2 wa = (na.xy * 0.5 + 0.5) * map_size - 0.5, wb = (nb.xy * 0.5 + 0.5) * map_size - 0.5;
  vec2 along = wb - wa;
  along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  vec2 corners[4] = vec2[4](wa - reach * (along + across), wa - reach * (along - across),
                            wb + reach * (along - across), wb + reach * (along + across));
  for (int i = 0; i < 4; ++i) {
    edge_start = wa;
    edge_end = wb;
    start_depth = na.z * 0.5 + 0.5;
    end_depth = nb.z * 0.5 + 0.5;
    gl_Position = window_vertex(corners[i], 0.0);
    EmitVertex();
  }
  EndPrimitive();
}

void main() {
  vec3 p[3] = vec3[3](world_position[0], world_position[2], world_position[4]);
  vec3 across[3] = vec3[3](world_position[1], world_position[3], world_position[5]);
  float f = facing(p[0], p[1], p[2]);
  if (!(abs(f) > 0.0)) return;  // edge-on to the light: its neighbours draw its silhouettes
  for (int i = 0; i < 3; ++i) {
    vec3 a = p[i], b = p[(i + 1) % 3];
    bool border = across[i] == p[(i + 2) % 3];  // no neighbour: the triangle turned over stands in
    // A silhouette edge, drawn once: by the triangle facing the light, or on a border by its own.
    if (border || (f > 0.0 && f * facing(b, a, across[i]) <= 0.0)) emit_edge(a, b);
  }
}
