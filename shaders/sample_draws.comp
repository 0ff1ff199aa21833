#version 450 core
// The GPU sampler's third pass, per band: each of the band's plants with points writes its draw,
// in plant order after the bands before, as the point splat reads them (first point, count, first sample,
// instance), and the draw of each block of points that starts in its run; each plant drawn as
// polygons its index for the polygon draws (instance.glsl, PLANT_INDEX).
#include "sample_common.glsl"
layout(local_size_x = 256) in;

#include "point_draws.glsl"
layout(std430, binding = 8) writeonly buffer BlockDraws { uint block_draws[]; };
layout(std430, binding = 16) writeonly buffer PolygonInstances { uint polygon_instances[]; };
const uint points_per_block = 16u;  // point_common.glsl
uniform uint block_capacity;        // beyond it the frame's points are not drawn

void main() {
  uvec2 band = this_band();
  uint place = gl_GlobalInvocationID.x;
  if (place >= band.y) return;
  uint i = band_list[band.x + place];
  Count c = count_of(i);
  if (c.points == 0u && !c.polygons) return;
  uvec4 at = in_group_offset(place) + group_sums[place / plants_per_group];
  if (c.points > 0u) {
    draw_points[at.y] = uvec2(at.x, c.points);
    draw_samples[at.y] = uvec2(plant_mesh(i).sizes.z, i);
    for (uint b = (at.x + points_per_block - 1u) / points_per_block; b * points_per_block < at.x + c.points && b < block_capacity; ++b) {
      block_draws[b] = at.y;
    }
  }
  if (c.polygons) polygon_instances[at.z] = i;
}
