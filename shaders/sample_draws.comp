#version 450 core
// The GPU sampler's last pass: each plant with points writes its draw, in plant order, as the
// point splat reads them (first point, count, first sample, instance), and the draw of each block
// of points that starts in its run.
#include "sample_common.glsl"
layout(local_size_x = 256) in;

layout(std430, binding = 1) writeonly buffer Draws { uvec4 draws[]; };
layout(std430, binding = 8) writeonly buffer BlockDraws { uint block_draws[]; };
const uint points_per_block = 16u;  // point_common.glsl
uniform uint block_capacity;  // beyond it the frame's points are not drawn

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= plant_count || counts[i].x == 0u) return;
  uvec2 at = offsets[i] + group_sums[i / plants_per_group];
  uint points = counts[i].x;
  draws[at.y] = uvec4(at.x, points, meshes[plant_meshes[i].x].sizes.z, i);
  for (uint b = (at.x + points_per_block - 1u) / points_per_block; b * points_per_block < at.x + points && b < block_capacity; ++b) block_draws[b] = at.y;
}
