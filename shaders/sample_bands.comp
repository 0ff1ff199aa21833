#version 450 core
// Between the band sort's passes, one work group: the counts per band and group of plants turned
// into first places in the band list (band-major exclusive prefix sums), each band's range, and
// the work groups each band's passes take, as glDispatchComputeIndirect commands; the lists'
// totals set to none.
#include "sample_common.glsl"
layout(local_size_x = 256) in;

layout(std430, binding = 23) buffer GroupBands { uint group_bands[]; };
// Per band: the groups of its count pass (plants_per_group plants each), then of its draw pass
// (256 plants each), each as (x, 1, 1, 0); a third, its part lists', and a fourth, its part masks'
// (sample_groups.comp).
layout(std430, binding = 24) writeonly buffer BandDispatch { uvec4 band_dispatch[]; };
uniform uint group_count;
uniform uint band_count;
// Where the sorted plants' places begin in the band list, and the first band's number there from
// 0: both 0 for the frame's sort, which also starts the lists; after it, the sort of the plants
// hidden in the frame into a band of their own.
uniform uint list_start;
uniform uint first_band;

#include "group_scan.glsl"

void main() {
  uint t = gl_LocalInvocationID.x;
  if (t == 0u && list_start == 0u) {
    total_points = 0u;
    draw_count = 0u;
    band_first_point = 0u;
    frame_points = 0u;
    all_points = 0u;
    polygon_count = 0u;
    part_plants_used = 0u;
  }
  uint carried = list_start;
  uint cells = group_count * band_count;
  for (uint first = 0u; first < cells; first += 256u) {
    uint own = first + t < cells ? group_bands[first + t] : 0u;
    uint chunk;
    uint sum = inclusive_sum(own, chunk);
    if (first + t < cells) group_bands[first + t] = carried + sum - own;
    carried += chunk;
  }
  memoryBarrierBuffer();
  barrier();
  for (uint b = t; b < band_count; b += 256u) {
    uint start = group_bands[b * group_count];
    uint end = b + 1u < band_count ? group_bands[(b + 1u) * group_count] : carried;
    band_ranges[first_band + b] = uvec2(start, end - start);
    band_dispatch[4u * (first_band + b)] = uvec4((end - start + plants_per_group - 1u) / plants_per_group, 1u, 1u, 0u);
    band_dispatch[4u * (first_band + b) + 1u] = uvec4((end - start + 255u) / 256u, 1u, 1u, 0u);
  }
}
