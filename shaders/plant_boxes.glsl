// A plant's bounds box (sample_common.glsl's SampledMesh, placed by its model matrix) against an
// image and a pyramid over it (depth_pyramid.glsl).

// The NDC rectangle of a box (its centre and half sizes in the frame `model` places) through `m`,
// and its nearest NDC depth; false where the box reaches behind the eye.
bool placed_box_rect(mat4 m, mat4 model, vec3 center, vec3 half_size, out vec3 lo, out vec3 hi) {
  lo = vec3(1e30);
  hi = vec3(-1e30);
  for (int c = 0; c < 8; ++c) {
    vec3 corner = center + half_size * vec3((c & 1) != 0 ? 1.0 : -1.0, (c & 2) != 0 ? 1.0 : -1.0, (c & 4) != 0 ? 1.0 : -1.0);
    vec4 clip = m * (model * vec4(corner, 1.0));
    if (!(clip.w > 0.0)) return false;
    vec3 ndc = clip.xyz / clip.w;
    lo = min(lo, ndc);
    hi = max(hi, ndc);
  }
  return true;
}

// The same of the plant's bounds box.
bool box_rect(mat4 m, mat4 model, SampledMesh mesh, out vec3 lo, out vec3 hi) {
  return placed_box_rect(m, model, mesh.center_radius.xyz, mesh.half_size_area.xyz, lo, hi);
}

// The pyramid texels over an NDC rectangle.
void texels_of(vec3 lo, vec3 hi, out ivec2 first, out ivec2 last) {
  vec2 size = vec2(pyramid_size[0]);
  first = ivec2(floor((lo.xy * 0.5 + 0.5) * size));
  last = ivec2(floor((hi.xy * 0.5 + 0.5) * size));
}

bool off_image(vec3 lo, vec3 hi) { return any(lessThan(hi.xy, vec2(-1.0))) || any(greaterThan(lo.xy, vec2(1.0))); }

// Whether a box's NDC rectangle and nearest depth (placed_box_rect) is off the image or, with
// `occlusion`, behind what the pyramid holds over all of it.
bool rect_hidden(vec3 lo, vec3 hi, bool occlusion) {
  if (off_image(lo, hi)) return true;
  if (!occlusion) return false;
  ivec2 first, last;
  texels_of(lo, hi, first, last);
  return all_nearer(first, last, lo.z * 0.5 + 0.5, false);
}

// The same of a box (centre and half sizes in the frame `model` places) through `m`. Not where it
// reaches behind the eye.
bool box_hidden(mat4 m, mat4 model, vec3 center, vec3 half_size, bool occlusion) {
  vec3 lo, hi;
  return placed_box_rect(m, model, center, half_size, lo, hi) && rect_hidden(lo, hi, occlusion);
}

// Whether a caster's box (centre and half sizes in the frame `model` places) covers no receiver
// farther from the light than its nearest point, in the mask the pyramid holds over the image of a
// shadow view (`map`: its world → clip matrix; the receivers' farthest window depths,
// receiver_marks.comp); false where it reaches behind the light.
bool shadows_nothing(mat4 map, mat4 model, vec3 center, vec3 half_size) {
  vec3 lo, hi;
  if (!placed_box_rect(map, model, center, half_size, lo, hi)) return false;
  if (off_image(lo, hi)) return true;
  ivec2 first, last;
  texels_of(lo, hi, first, last);
  return all_nearer(first, last, max(lo.z * 0.5 + 0.5, 0.0), true);
}

bool shadows_nothing(mat4 map, mat4 model, SampledMesh mesh) {
  return shadows_nothing(map, model, mesh.center_radius.xyz, mesh.half_size_area.xyz);
}
