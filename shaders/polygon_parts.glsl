// The polygon parts of the point meshes (pointgen::split_triangles, at most 64 a mesh), all meshes'
// in one list (sample_common.glsl's SampledMesh: its first and their number), and the lanes of a
// table's polygon draws: one per part, drawing the plants that show that part and not all of
// them, and a last one drawing the plants whole (part_masks.comp, part_lists.comp,
// layer_casters.comp).
struct PolygonPart {
  vec4 center;     // of its triangles' box, in the mesh's frame
  vec4 half_size;
  uvec4 indices;   // its first index after the mesh's first, its index count, 0, 0
};
layout(std430, binding = 25) readonly buffer PolygonParts { PolygonPart polygon_parts[]; };
// Per table of plants: (first plant, end, 0, 0), then (index count, first index, base vertex, 0).
layout(std430, binding = 18) readonly buffer Tables { uvec4 tables[]; };

// A plant whose box covers more than this many pixels of a view's image is drawn by parts; for a
// smaller one the parts' draws cost more than the triangles they leave out (pointgen/sampling/
// view_sampler.cpp).
const float pixels_to_split = 1024.0;
// The parts a plant draws, a bit each; this where it draws all of them, as one draw.
const uvec2 drawn_whole = uvec2(0xFFFFFFFFu);
const uint lanes = 65u, whole_lane = 64u;

uvec2 every_part(uint parts) {
  return uvec2(parts >= 32u ? 0xFFFFFFFFu : (1u << parts) - 1u, parts >= 64u ? 0xFFFFFFFFu : parts > 32u ? (1u << (parts - 32u)) - 1u : 0u);
}

bool in_lane(uvec2 drawn, uint lane) {
  if (lane == whole_lane) return drawn == drawn_whole;
  return drawn != drawn_whole && ((drawn[lane / 32u] >> (lane % 32u)) & 1u) != 0u;
}

// The band's polygon plants (after its groups pass, sample_groups.comp): their first place in the
// list of the frame's polygon plants, and the end.
uvec2 band_polygons() {
  uvec2 band = this_band();
  return uvec2(band.y > 0u ? in_group_offset(0u).z + group_sums[0].z : polygon_count, polygon_count);
}

// The passes with a work group per polygon plant (part_masks.comp, layer_casters.comp) lay their
// groups in rows.
#include "group_rows.glsl"

// The pixels a rectangle of NDC covers in an image of `pixels`.
float pixels_in(vec3 lo, vec3 hi, vec2 pixels) {
  vec2 extent = 0.5 * (hi.xy - lo.xy) * pixels;
  return extent.x * extent.y;
}

// The index count and first index of a table's draws in `lane`: its mesh's part, or the whole mesh
// in the last lane; no indices for a part its mesh does not have.
uvec2 lane_indices(uint table, uint lane) {
  uvec4 plants = tables[2u * table], mesh_draw = tables[2u * table + 1u];
  if (lane == whole_lane) return mesh_draw.xy;
  uvec4 parts = plant_mesh(plants.x).polygon_parts;
  if (lane >= parts.y) return uvec2(0u, mesh_draw.y);
  uvec4 part = polygon_parts[parts.x + lane].indices;
  return uvec2(part.y, mesh_draw.y + part.x);
}
