#version 450 core
// Before a splat's passes: the work groups they take for the list's points (point_threads.glsl),
// as a glDispatchComputeIndirect command, in rows (group_rows.glsl).
layout(local_size_x = 1) in;

layout(std430, binding = 15) readonly buffer Totals { uint total_points; uint draw_count; uint band_first_point; uint frame_points; };
layout(std430, binding = 16) writeonly buffer Dispatch { uvec3 groups; };

const uint points_per_group = 64u * 16u;  // threads per group × points_per_thread (point_threads.glsl)
uniform bool band_only;  // for the points of the band last added
uniform bool map_points;  // for those the frame does not show too

#include "group_rows.glsl"

void main() {
  uint end = map_points ? total_points : frame_points, start = band_only ? band_first_point : 0u;
  uint points = end > start ? end - start : 0u;
  uint needed = (points + points_per_group - 1u) / points_per_group;
  groups = group_rows(needed).xyz;
}
