#version 450 core
// The GPU sampler's pass after part_masks.comp, for a band with polygon plants, a work group per
// lane: lane p < 64 lists the band's polygon plants that draw part p alone of their parts, the
// last lane those drawn whole, each list in plant order; then the lane's draw per table of plants
// (a DrawElementsIndirectCommand whose base instance is the list's first place). A lane's threads
// take a run of the band's polygon plants each, so the lists need no sort; a list's place in the
// buffer is taken by an atomic add, which moves no plant's turn in the frame's draws.
#include "sample_common.glsl"
#include "polygon_parts.glsl"
layout(local_size_x = 256) in;

layout(std430, binding = 16) readonly buffer PolygonInstances { uint polygon_instances[]; };
layout(std430, binding = 26) readonly buffer PartMasks { uvec2 part_masks[]; };
layout(std430, binding = 27) coherent buffer PartPlants { uint part_plants[]; };
layout(std430, binding = 29) writeonly buffer PartCommands { uint part_commands[]; };
uniform uint table_count;
uniform uint part_plant_capacity;  // the list's room: plants past it are not drawn
uniform uint first_command;        // this band's first command

// The first place in list[first, end) whose plant is `plant` or after it (lists hold plants in order).
uint place_of(uint first, uint end, uint plant) {
  while (first < end) {
    uint mid = (first + end) / 2u;
    if (part_plants[mid] < plant) first = mid + 1u; else end = mid;
  }
  return first;
}

#include "group_scan.glsl"
shared uint list_first;

void main() {
  uint lane = gl_WorkGroupID.x, t = gl_LocalInvocationID.x;
  uvec2 polygons = band_polygons();
  uint run = (polygons.y - polygons.x + 255u) / 256u;
  uint first = min(polygons.x + t * run, polygons.y), end = min(first + run, polygons.y);
  uint own = 0u;
  for (uint s = first; s < end; ++s) own += in_lane(part_masks[s], lane) ? 1u : 0u;
  uint total;
  uint sum = inclusive_sum(own, total);
  if (t == 255u) list_first = atomicAdd(part_plants_used, total);
  barrier();
  uint listed = min(total, part_plant_capacity - min(list_first, part_plant_capacity));
  uint at = list_first + sum - own;
  for (uint s = first; s < end; ++s) {
    if (!in_lane(part_masks[s], lane)) continue;
    if (at < list_first + listed) part_plants[at] = polygon_instances[s];
    ++at;
  }
  memoryBarrierBuffer();
  barrier();
  for (uint table = t; table < table_count; table += 256u) {
    uvec4 plants = tables[2u * table];
    uint from = place_of(list_first, list_first + listed, plants.x), to = place_of(list_first, list_first + listed, plants.y);
    uvec2 indices = lane_indices(table, lane);
    uint c = 5u * (first_command + table * lanes + lane);
    part_commands[c] = indices.x;
    part_commands[c + 1u] = indices.x > 0u ? to - from : 0u;
    part_commands[c + 2u] = indices.y;
    part_commands[c + 3u] = tables[2u * table + 1u].z;
    part_commands[c + 4u] = from;
  }
}
