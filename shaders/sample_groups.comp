#version 450 core
// The GPU sampler's second pass per band, one work group: the band's groups' sums turned into
// their exclusive prefix sums after the lists of the bands before, and the lists' new totals.
#include "sample_common.glsl"
#include "polygon_parts.glsl"
layout(local_size_x = 256) in;

// Per band three dispatches (sample_bands.comp); the third, of its part lists (part_lists.comp: a
// work group per lane), none where the band has no polygon plants.
layout(std430, binding = 24) writeonly buffer BandDispatch { uvec4 band_dispatch[]; };
uniform uint point_capacity;  // the points the splat's buffers hold: those past it are not drawn
uniform bool in_frame;         // the band is one the frame shows

shared uvec4 sums[256];

void main() {
  uint t = gl_LocalInvocationID.x;
  uint group_count = (this_band().y + plants_per_group - 1u) / plants_per_group;
  uvec4 carried = uvec4(all_points, draw_count, polygon_count, 0u);
  for (uint first = 0u; first < group_count; first += 256u) {
    uvec4 own = first + t < group_count ? group_sums[first + t] : uvec4(0u);
    sums[t] = own;
    barrier();
    for (uint step = 1u; step < 256u; step *= 2u) {
      uvec4 before = t >= step ? sums[t - step] : uvec4(0u);
      barrier();
      sums[t] += before;
      barrier();
    }
    if (first + t < group_count) group_sums[first + t] = carried + sums[t] - own;
    uvec4 chunk = sums[255];
    barrier();
    carried += chunk;
  }
  barrier();
  if (t == 0u) {
    band_dispatch[4u * (band_number - 1u) + 2u] = uvec4(carried.z > polygon_count ? lanes : 0u, 1u, 1u, 0u);
    band_dispatch[4u * (band_number - 1u) + 3u] = group_rows(carried.z - polygon_count);
    band_first_point = min(all_points, point_capacity);
    all_points = carried.x;
    total_points = min(carried.x, point_capacity);
    if (in_frame) frame_points = total_points;
    draw_count = carried.y;
    polygon_count = carried.z;
  }
}
