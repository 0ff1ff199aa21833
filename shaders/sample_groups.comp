#version 450 core
// The GPU sampler's second pass, one work group: the groups' sums turned into their exclusive
// prefix sums, and the frame's totals (points, plants with points) as a point splat reads them.
#include "sample_common.glsl"
layout(local_size_x = 256) in;

layout(std430, binding = 15) writeonly buffer Totals { uint total_points; uint draw_count; };

uniform uint group_count;
uniform uint point_capacity;  // the points the splat's buffers hold: those past it are not drawn

shared uvec2 sums[256];

void main() {
  uint t = gl_LocalInvocationID.x;
  uvec2 carried = uvec2(0u);
  for (uint first = 0u; first < group_count; first += 256u) {
    uvec2 own = first + t < group_count ? group_sums[first + t] : uvec2(0u);
    sums[t] = own;
    barrier();
    for (uint step = 1u; step < 256u; step *= 2u) {
      uvec2 before = t >= step ? sums[t - step] : uvec2(0u);
      barrier();
      sums[t] += before;
      barrier();
    }
    if (first + t < group_count) group_sums[first + t] = carried + sums[t] - own;
    uvec2 chunk = sums[255];
    barrier();
    carried += chunk;
  }
  if (t == 0u) {
    total_points = min(carried.x, point_capacity);
    draw_count = carried.y;
  }
}
