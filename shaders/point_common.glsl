// The buffers of a point splat (app/render/point_splat.hpp): the frame's draws (point_draws.glsl),
// the drawn instances, the surface samples, and per pixel the nearest point's depth, the point that
// has it and how much of it the points cover (point_coverage.glsl).
#include "point_draws.glsl"
#include "plant_instances.glsl"
#include "point_samples.glsl"
layout(std430, binding = 6) buffer Depths { uint depths[]; };
layout(std430, binding = 7) buffer Winners { uint winners[]; };
layout(std430, binding = 36) buffer Coverage { uint coverage[]; };
const float coverage_steps = 256.0;
// Per block of points_per_block points, the draw holding its first point.
layout(std430, binding = 8) readonly buffer BlockDraws { uint block_draws[]; };
const uint points_per_block = 16u;  // app/render/point_splat.cpp
// Per point, where the frame's depth pass put it: its splat (pack_splat) and its depth, or
// no_point as the depth where it fell outside the target.
layout(std430, binding = 9) buffer Projected { uvec2 projected[]; };
// Per pixel, the nearest depth of the frame's points whose centre falls in it, and the point that
// has it.
layout(std430, binding = 37) buffer CentreDepths { uint centre_depths[]; };
layout(std430, binding = 38) buffer CentreWinners { uint centre_winners[]; };

// A splat's lower-left pixel (x and y biased by 16 in 15 bits each, enough for the 16384-pixel
// targets --size allows) and the pixel its point falls in: the splat's middle one, or for an even
// splat size one of the two middle ones each way (a bit each).
uint pack_splat(ivec2 corner, ivec2 centre, int splat_size) {
  uvec2 upper = uvec2(clamp(centre - corner - (splat_size - 1) / 2, 0, 1));
  uvec2 biased = uvec2(corner + 16) & 0x7FFFu;
  return biased.x | (upper.x << 15) | (biased.y << 16) | (upper.y << 31);
}
ivec2 splat_corner(uint splat) { return ivec2(splat & 0x7FFFu, (splat >> 16) & 0x7FFFu) - 16; }
ivec2 splat_centre(uint splat, int splat_size) {
  return splat_corner(splat) + (splat_size - 1) / 2 + ivec2((splat >> 15) & 1u, splat >> 31);
}

// The list's size, in a buffer so that a list made on the GPU needs no read-back, where the points
// of the distance band last added begin, and how many of them the frame shows (the rest are for
// shadow maps alone: app/render/gpu_sampler.hpp).
layout(std430, binding = 15) readonly buffer Totals { uint total_points; uint draw_count; uint band_first_point; uint frame_points; };

const uint no_point = 0xFFFFFFFFu;
uniform ivec2 target_size;

const int coverage_margin = 8;  // a 16-pixel splat's corner lies up to 8 pixels off the target
// The coverage entry of the splats whose corner is `entry` - coverage_margin.
uint coverage_entry(ivec2 entry) { return uint(entry.y * (target_size.x + coverage_margin) + entry.x); }

// The draw holding point p: the last one whose first point is at most p, found from the draw
// holding the first point of p's block in a step or a few, where a binary search over a frame's
// hundred thousand draws takes 17.
uint draw_of(uint p) {
  uint d = block_draws[p / points_per_block];
  while (d + 1u < draw_count && draw_points[d + 1u].x <= p) ++d;
  return d;
}

uint sample_of(uint p, uint draw) { return draw_samples[draw].x + (p - draw_points[draw].x); }
