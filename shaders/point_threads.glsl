// The splat compute passes' threads: each takes a run of points_per_thread consecutive points and
// visits the splat_size x splat_size pixels of each. The work groups are laid out in rows of up to
// GL's 65535 (group_rows.glsl, point_dispatch.comp).
layout(local_size_x = 64) in;

uniform int splat_size;
uniform bool band_only;  // only the points of the band last added, not the whole list
uniform bool map_points;  // also the points for shadow maps alone, which the frame does not show

const uint points_per_thread = 16u;

#include "group_rows.glsl"

// This thread's points, from x up to y (none when x >= y).
uvec2 thread_points() {
  uint first = (band_only ? band_first_point : 0u) + (group_number() * gl_WorkGroupSize.x + gl_LocalInvocationID.x) * points_per_thread;
  return uvec2(first, min(first + points_per_thread, map_points ? total_points : frame_points));
}

// The index of pixel (x, y) of a splat whose lower-left pixel is `corner`; no_point off the target.
uint splat_pixel(ivec2 corner, int x, int y) {
  ivec2 pixel = corner + ivec2(x, y);
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, target_size))) return no_point;
  return uint(pixel.y * target_size.x + pixel.x);
}
