#version 450 core
// The GPU sampler's last pass, per band: for each table of point meshes, the indirect draw of its
// plants this band drew as polygons (a DrawElementsIndirectCommand: index count, instances, first
// index, base vertex, base instance), read from the prefix sums of the band's polygon plants.
// The frame's draws of the band's polygon plants by part are emptied here, for a band without
// polygon plants, whose part lists are not made (part_lists.comp).
#include "sample_common.glsl"
#include "polygon_parts.glsl"
layout(local_size_x = 64) in;

layout(std430, binding = 19) writeonly buffer Commands { uint commands[]; };
layout(std430, binding = 29) writeonly buffer PartCommands { uint part_commands[]; };
uniform uint table_count;

// The first place in the band whose plant is `plant` or after it (the band holds plants in order).
uint place_of(uvec2 band, uint plant) {
  uint lo = 0u, hi = band.y;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (band_list[band.x + mid] < plant) lo = mid + 1u; else hi = mid;
  }
  return lo;
}

// The polygon plants before a place in the band, in the lists of this band and the bands' before.
uint polygons_before(uvec2 band, uint place) {
  return place < band.y ? in_group_offset(place).z + group_sums[place / plants_per_group].z : polygon_count;
}

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= table_count) return;
  uvec4 plants = tables[2u * t], mesh = tables[2u * t + 1u];
  uvec2 band = this_band();
  uint first = polygons_before(band, place_of(band, plants.x)), end = polygons_before(band, place_of(band, plants.y));
  uint at = 5u * ((band_number - 1u) * table_count + t);
  commands[at] = mesh.x;
  commands[at + 1u] = end - first;
  commands[at + 2u] = mesh.y;
  commands[at + 3u] = mesh.z;
  commands[at + 4u] = first;
  uint first_part_command = ((band_number - 1u) * table_count + t) * lanes;
  for (uint lane = 0u; lane < lanes; ++lane) part_commands[5u * (first_part_command + lane) + 1u] = 0u;
}
