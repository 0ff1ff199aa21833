#version 450 core
// Before a splat's passes: the work groups they take for the list's points (point_threads.glsl),
// as a glDispatchComputeIndirect command, in rows of at most GL's guaranteed 65535 groups.
layout(local_size_x = 1) in;

layout(std430, binding = 15) readonly buffer Totals { uint total_points; uint draw_count; uint band_first_point; uint frame_points; };
layout(std430, binding = 16) writeonly buffer Dispatch { uvec3 groups; };

const uint points_per_group = 64u * 16u;  // threads per group × points_per_thread (point_threads.glsl)
const uint max_row = 65535u;
uniform bool band_only;  // for the points of the band last added
uniform bool map_points;  // for those the frame does not show too

void main() {
  uint end = map_points ? total_points : frame_points, start = band_only ? band_first_point : 0u;
  uint points = end > start ? end - start : 0u;
  uint needed = (points + points_per_group - 1u) / points_per_group;
  uint rows = (needed + max_row - 1u) / max_row;
  groups = needed == 0u ? uvec3(0u, 1u, 1u) : uvec3(rows == 1u ? needed : max_row, rows, 1u);
}
