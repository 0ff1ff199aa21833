#version 450 core
// Point samples rasterized as one-pixel GL_POINTS (app/bench/point_raster.hpp). Vertex v of a draw
// is one surface sample of one drawn instance:
//  - one draw over all points: v is the running point index; the draw holding it is found by
//    binary search in `draws` (first point, count, first sample, instance), as the compute splat does;
//  - indirect draws: v is the sample index itself (a command's `first` is its mesh's first sample),
//    and the instance comes from an attribute with divisor 1 (a command's baseInstance).
layout(std430, binding = 0) readonly buffer Draws { uvec4 draws[]; };
#include "plant_instances.glsl"
#include "point_samples.glsl"

layout(location = 0) in uint instance_attribute;  // indirect draws only
uniform bool indirect;
uniform uint draw_count;
uniform mat4 view_projection;
out vec3 point_color;

uint draw_of(uint p) {
  uint lo = 0u, hi = draw_count - 1u;
  while (lo < hi) {
    uint mid = (lo + hi + 1u) / 2u;
    if (draws[mid].x <= p) lo = mid; else hi = mid - 1u;
  }
  return lo;
}

void main() {
  uint sample_index = uint(gl_VertexID), instance = instance_attribute;
  if (!indirect) {
    uvec4 draw = draws[draw_of(sample_index)];
    sample_index = draw.z + (sample_index - draw.x);
    instance = draw.w;
  }
  gl_Position = view_projection * (instance_model(instance) * vec4(sample_position(sample_index), 1.0));
  point_color = sample_color(sample_index) * instance_tint(instance);
}
