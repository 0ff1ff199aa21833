// The buffers of a point splat (app/render/point_splat.hpp): the frame's draws (first point,
// point count, first sample, instance), the drawn instances, the surface samples, and per pixel
// the nearest point's depth and the point that has it.
struct Instance {
  mat4 model;
  vec4 tint;
};
layout(std430, binding = 1) readonly buffer Draws { uvec4 draws[]; };
layout(std430, binding = 2) readonly buffer Instances { Instance instances[]; };
layout(std430, binding = 3) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 4) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = 5) readonly buffer Colors { vec4 colors[]; };
layout(std430, binding = 6) buffer Depths { uint depths[]; };
layout(std430, binding = 7) buffer Winners { uint winners[]; };

const uint no_point = 0xFFFFFFFFu;
uniform uint draw_count;
uniform ivec2 target_size;

// The draw holding point p: the last one whose first point is at most p.
uint draw_of(uint p) {
  uint lo = 0u, hi = draw_count - 1u;
  while (lo < hi) {
    uint mid = (lo + hi + 1u) / 2u;
    if (draws[mid].x <= p) lo = mid; else hi = mid - 1u;
  }
  return lo;
}

uint sample_of(uint p, uint draw) { return draws[draw].z + (p - draws[draw].x); }
