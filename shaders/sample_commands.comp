#version 450 core
// The GPU sampler's last pass, per band: for each table of point meshes, the indirect draw of its
// plants this band drew as polygons (a DrawElementsIndirectCommand: index count, instances, first
// index, base vertex, base instance), read from the prefix sums of the band's polygon plants.
#include "sample_common.glsl"
layout(local_size_x = 64) in;

layout(std430, binding = 18) readonly buffer Tables { uvec4 tables[]; };  // first plant, end, index count, 0
layout(std430, binding = 19) writeonly buffer Commands { uint commands[]; };
uniform uint table_count;
uniform uint band_number;  // from 1

// The polygon plants before `plant` in the lists, this band's and the bands' before.
uint polygons_before(uint plant) {
  return plant < plant_count ? offsets[plant].z + group_sums[plant / plants_per_group].z : polygon_count;
}

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= table_count) return;
  uvec4 table = tables[t];
  uint first = polygons_before(table.x), end = polygons_before(table.y);
  uint at = 5u * ((band_number - 1u) * table_count + t);
  commands[at] = table.z;
  commands[at + 1u] = end - first;
  commands[at + 2u] = 0u;
  commands[at + 3u] = 0u;
  commands[at + 4u] = first;
}
