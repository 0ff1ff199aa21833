#version 450 core
// The GPU sampler's count pass, per band: each of the band's plants (in view, sample_bins.comp)
// culled, with occlusion, against the depth pyramid of what nearer bands drew (and marked so, for
// the band of hidden plants the shadow maps draw: sample_bins.comp); counted with the
// density formula (docs/point_density.md); points or polygons chosen as pointgen::sample_view
// chooses them. Then the prefix sums of the counts within each work group.
#include "sample_common.glsl"
#define MARKS_CHANGES
#include "depth_pyramid.glsl"
#include "plant_boxes.glsl"
layout(local_size_x = 256) in;

uniform mat4 view_projection;  // the first view's, for occlusion
uniform bool occlusion;
const int changed_margin = 10;
// For the shadow maps' own bands (casters out of view, plants the frame hides): no more points than
// the shadow view asks (points_a_map_asks), whatever the camera's density asks.
uniform bool cap_to_map;
uniform mat4 map_view_projection;
uniform float map_texels;
// For those bands: only plants whose box covers a receiver the frame shows farther from the light,
// as marked in the pyramid bound (then a receiver mask over the shadow view's image, DepthPyramid).
uniform bool receivers_only;
uniform vec3 eye;
uniform vec3 forward;
uniform float edge_cos;
uniform float pixels_per_radian;
uniform float k;
uniform float points_per_triangle;


// (points, 1 when drawn as polygons, 1 when hidden) of plant i.
uvec3 count_plant(uint i) {
  mat4 model = instance_model(i);
  SampledMesh mesh = plant_mesh(i);
  // Off screen or behind what nearer bands drew over all of its bounds box's rectangle.
  vec3 lo, hi;
  bool before_eye = occlusion && box_rect(view_projection, model, mesh, lo, hi);
  if (before_eye && rect_hidden(lo, hi, true)) return uvec3(0u, 0u, 1u);
  if (receivers_only && shadows_nothing(map_view_projection, model, mesh)) return uvec3(0u);
  float needed = points_needed(model, mesh, eye, forward, edge_cos, pixels_per_radian, k);
  if (cap_to_map) {
    float scale = model_scale(model);
    vec3 center = (model * vec4(mesh.center_radius.xyz, 1.0)).xyz;
    needed = min(needed, points_a_map_asks(map_view_projection, map_texels, k, center, mesh.half_size_area.w * scale * scale));
  }
  float samples = float(mesh.sizes.y);
  float ratio = triangles_ratio(needed, mesh, points_per_triangle);
  bool polygons = as_polygons(needed, mesh, points_per_triangle);
  float drawn = (polygons ? clamp((band_high - ratio) / (band_high - band_low), 0.0, 1.0) : 1.0) * needed;
  uint points = uint(min(floor(drawn + plant_rounding(i)), samples));
  bool as_points = ratio < band_high && mesh.sizes.y > 0u;
  // What the frame draws of it may change the pyramid's tiles under its rectangle (all where its
  // box reaches behind the eye): a 16-pixel splat reaches 8 pixels past its point, level 0 one
  // more, and the rectangle's texels are rounded down.
  if (occlusion && ((as_points && points > 0u) || polygons)) {
    if (before_eye) {
      ivec2 first, last;
      texels_of(lo, hi, first, last);
      mark_changed(first, last, changed_margin);
    } else {
      mark_changed(ivec2(0), pyramid_size[0] - 1, 0);
    }
  }
  return uvec3(as_points ? points : 0u, polygons ? 1u : 0u, 0u);
}

shared uvec4 sums[256];

void main() {
  uvec2 band = this_band();
  uint first = gl_WorkGroupID.x * plants_per_group + gl_LocalInvocationID.x * 4u;  // places in the band
  uvec4 own[4];
  uvec4 total = uvec4(0u);
  for (uint j = 0u; j < 4u; ++j) {
    own[j] = total;
    if (first + j >= band.y) continue;
    uint plant = band_list[band.x + first + j];
    uvec3 c = count_plant(plant);
    total += uvec4(c.x, c.x > 0u ? 1u : 0u, c.y, 0u);
    counts[plant] = packed_count(c.x, band_number, c.y != 0u, c.z != 0u);
  }
  // Inclusive scan of the threads' totals (Hillis-Steele), then each plant's exclusive offset.
  uint t = gl_LocalInvocationID.x;
  sums[t] = total;
  barrier();
  for (uint step = 1u; step < 256u; step *= 2u) {
    uvec4 before = t >= step ? sums[t - step] : uvec4(0u);
    barrier();
    sums[t] += before;
    barrier();
  }
  uvec4 thread_offset = sums[t] - total;
  for (uint j = 0u; j < 4u; ++j) {
    if (first + j < band.y) set_in_group_offset(first + j, thread_offset + own[j]);
  }
  if (t == 255u) group_sums[gl_WorkGroupID.x] = sums[t];
}
