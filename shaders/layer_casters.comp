#version 450 core
// The polygon plants of a frame (every band's, casters' included) that shadow what one shadow view
// serves (a cascade, or a single map): those whose bounds box in its image covers a receiver of the
// mask over it (DepthPyramid::build_receivers, the surfaces that look up this view), and of a plant
// that covers more than pixels_to_split texels there, only the parts whose boxes do; listed per
// table and lane (polygon_parts.glsl) with an indirect draw each. The order within a list follows
// the threads' atomics: a depth-only map keeps the nearest depth whatever the order. Passes: START
// (one work group) clears the lists' counts and sizes the per-plant passes from the frame's polygon
// plants; the per-plant pass counts each list's plants (`writing` false), then, after PLACE (one
// work group: each list's place, by a prefix sum, and its command), writes each plant's index into
// the lists it is in.
#include "sample_common.glsl"
#include "depth_pyramid.glsl"
#include "plant_boxes.glsl"
#include "polygon_parts.glsl"
#include "plant_parts.glsl"

layout(std430, binding = 16) readonly buffer PolygonInstances { uint polygon_instances[]; };
// The per-plant passes' work groups (a glDispatchComputeIndirect command), then per list (table by
// lane) two: its plants, then, once placed, its end and its next place (a uint each, as atomics
// take them).
layout(std430, binding = 31) buffer LayerCounts {
  uvec4 layer_dispatch;
  uint layer_counts[];
};
layout(std430, binding = 32) writeonly buffer LayerPlants { uint layer_plants[]; };
layout(std430, binding = 33) writeonly buffer LayerCommands { uint layer_commands[]; };
uniform uint table_count;

#if defined(START)
layout(local_size_x = 256) in;  // one work group
void main() {
  for (uint c = gl_LocalInvocationID.x; c < 2u * table_count * lanes; c += 256u) layer_counts[c] = 0u;
  if (gl_LocalInvocationID.x == 0u) layer_dispatch = group_rows(polygon_count);
}
#elif defined(PLACE)
#include "group_scan.glsl"
layout(local_size_x = 256) in;  // one work group, a run of lists a thread
uniform uint first_command;  // the view's commands: `lanes` per table from here
uniform uint capacity;       // the places in layer_plants: lists past them are cut short
void main() {
  uint lists = table_count * lanes, run = (lists + 255u) / 256u;
  uint first_list = min(gl_LocalInvocationID.x * run, lists), end = min(first_list + run, lists);
  uint own = 0u;
  for (uint list = first_list; list < end; ++list) own += layer_counts[2u * list];
  uint total;
  uint before = inclusive_sum(own, total) - own;  // the plants of the lists before, uncut
  for (uint list = first_list; list < end; ++list) {
    uint wanted = layer_counts[2u * list];
    uint first = min(before, capacity);
    uint plants = min(before + wanted, capacity) - first;
    uvec2 indices = lane_indices(list / lanes, list % lanes);
    uint at = 5u * (first_command + list);
    layer_commands[at] = indices.x;
    layer_commands[at + 1u] = indices.x > 0u ? plants : 0u;
    layer_commands[at + 2u] = indices.y;
    layer_commands[at + 3u] = tables[2u * (list / lanes) + 1u].z;
    layer_commands[at + 4u] = first;
    layer_counts[2u * list] = first + plants;
    layer_counts[2u * list + 1u] = first;
    before += wanted;
  }
}
#else
layout(local_size_x = 64) in;  // a work group per polygon plant, a part each
uniform mat4 map_view_projection;
uniform vec2 pixels;  // the view's image
uniform bool writing;

// The table holding a plant (the tables hold plants in order).
uint table_of(uint plant) {
  uint lo = 0u, hi = table_count - 1u;
  while (lo < hi) {
    uint mid = (lo + hi + 1u) / 2u;
    if (tables[2u * mid].x <= plant) lo = mid; else hi = mid - 1u;
  }
  return lo;
}

void add_to(uint list, uint plant) {
  if (!writing) {
    atomicAdd(layer_counts[2u * list], 1u);
    return;
  }
  uint at = atomicAdd(layer_counts[2u * list + 1u], 1u);
  if (at < layer_counts[2u * list]) layer_plants[at] = plant;
}

void main() {
  uint slot = group_number();
  if (slot >= polygon_count) return;
  uint plant = polygon_instances[slot];
  if (!count_of(plant).polygons) return;  // the map draws it as points (sample_bins.comp, HIDDEN_KEYS)
  mat4 model = instance_model(plant);
  SampledMesh mesh = plant_mesh(plant);
  if (shadows_nothing(map_view_projection, model, mesh)) return;
  uint first_list = table_of(plant) * lanes;
  uvec2 casting = parts_kept(map_view_projection, pixels, model, mesh, true, false);
  uint part = gl_LocalInvocationID.x;  // this thread's list: its part's, and thread 0 the whole plants'
  if (casting == drawn_whole) {
    if (part == 0u) add_to(first_list + whole_lane, plant);
  } else if (in_lane(casting, part)) {
    add_to(first_list + part, plant);
  }
}
#endif
