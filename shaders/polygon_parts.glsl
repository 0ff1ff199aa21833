// The polygon parts of the point meshes (pointgen::split_triangles, at most 64 a mesh), all meshes'
// in one list (sample_common.glsl's SampledMesh: its first and their number), and the masks of
// parts a polygon plant draws (part_masks.comp, part_lists.comp).
struct PolygonPart {
  vec4 center;     // of its triangles' box, in the mesh's frame
  vec4 half_size;
  uvec4 indices;   // its first index after the mesh's first, its index count, 0, 0
};
layout(std430, binding = 25) readonly buffer PolygonParts { PolygonPart polygon_parts[]; };

// A plant larger than this many pixels on screen (its box's rectangle) is drawn by parts; for a
// smaller one the parts' draws cost more than the triangles they leave out (pointgen/sampling/
// view_sampler.cpp).
const float pixels_to_split = 1024.0;
// The mask of a plant drawn whole: one draw of all of its triangles.
const uvec2 drawn_whole = uvec2(0xFFFFFFFFu);

uvec2 every_part(uint parts) {
  return uvec2(parts >= 32u ? 0xFFFFFFFFu : (1u << parts) - 1u, parts >= 64u ? 0xFFFFFFFFu : parts > 32u ? (1u << (parts - 32u)) - 1u : 0u);
}
