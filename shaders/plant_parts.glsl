// Which of a polygon plant's parts a view draws (polygon_parts.glsl; after sample_common.glsl,
// depth_pyramid.glsl and plant_boxes.glsl): for the frame (part_masks.comp) those whose boxes are
// on screen and, with `occlusion`, not behind the pyramid; for a shadow map (`receivers`,
// layer_casters.comp) those whose boxes cover a receiver farther from the light in the mask the
// pyramid holds. A plant whose box covers no more than pixels_to_split pixels of the view's image
// through `m`, or reaches behind the eye, or whose mesh has no parts, is drawn whole, as is one
// that keeps every part: drawn_whole. Else a bit per part kept.
//
// A work group of 64 threads asks together, a part each (thread p tests part p), and each gets the
// answer: a thread walking a plant's 64 parts alone, each up to 16 × 16 pyramid texels, took 15 ms
// a 1080p frame on an H200 (its reads wait one after another). Call from uniform control flow.
shared uint kept_parts[2];

uvec2 parts_kept(mat4 m, vec2 pixels, mat4 model, SampledMesh mesh, bool receivers, bool occlusion) {
  uint p = gl_LocalInvocationID.x;
  if (p < 2u) kept_parts[p] = 0u;
  barrier();
  vec3 lo, hi;
  bool by_parts = mesh.polygon_parts.y > 0u && box_rect(m, model, mesh, lo, hi) && pixels_in(lo, hi, pixels) > pixels_to_split;
  if (by_parts && p < mesh.polygon_parts.y) {
    PolygonPart part = polygon_parts[mesh.polygon_parts.x + p];
    bool dropped = receivers ? shadows_nothing(m, model, part.center.xyz, part.half_size.xyz)
                             : box_hidden(m, model, part.center.xyz, part.half_size.xyz, occlusion);
    if (!dropped) atomicOr(kept_parts[p / 32u], 1u << (p % 32u));
  }
  barrier();
  uvec2 kept = uvec2(kept_parts[0], kept_parts[1]);
  return !by_parts || kept == every_part(mesh.polygon_parts.y) ? drawn_whole : kept;
}
