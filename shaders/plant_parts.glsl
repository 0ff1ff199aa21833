// Which of a polygon plant's parts a view draws (polygon_parts.glsl; after sample_common.glsl,
// depth_pyramid.glsl and plant_boxes.glsl): for the frame (part_masks.comp) those whose boxes are
// on screen and, with `occlusion`, not behind the pyramid; for a shadow map (`receivers`,
// layer_casters.comp) those whose boxes cover a receiver farther from the light in the mask the
// pyramid holds. A plant whose box covers no more than pixels_to_split pixels of the view's image
// through `m`, or reaches behind the eye, or whose mesh has no parts, is drawn whole, as is one
// that keeps every part: drawn_whole. Else a bit per part kept.
uvec2 parts_kept(mat4 m, vec2 pixels, mat4 model, SampledMesh mesh, bool receivers, bool occlusion) {
  vec3 lo, hi;
  if (mesh.polygon_parts.y == 0u || !box_rect(m, model, mesh, lo, hi)) return drawn_whole;
  if (!(pixels_in(lo, hi, pixels) > pixels_to_split)) return drawn_whole;
  uvec2 kept = uvec2(0u);
  for (uint p = 0u; p < mesh.polygon_parts.y; ++p) {
    PolygonPart part = polygon_parts[mesh.polygon_parts.x + p];
    bool dropped = receivers ? shadows_nothing(m, model, part.center.xyz, part.half_size.xyz)
                             : box_hidden(m, model, part.center.xyz, part.half_size.xyz, occlusion);
    if (!dropped) kept[p / 32u] |= 1u << (p % 32u);
  }
  return kept == every_part(mesh.polygon_parts.y) ? drawn_whole : kept;
}
