#version 450 core
// The polygon plants of a frame (every band's, casters' included) that shadow what one shadow view
// of several (a cascade) serves: those whose bounds box in its image covers a receiver of the
// mask over it (DepthPyramid::build_receivers, the surfaces that look up this view), listed per
// table with an indirect draw each, so that a cascade draws its own casters, not every cascade's. The order within a table follows the threads' atomics:
// a depth-only map keeps the nearest depth whatever the order. Passes: START (one thread) clears
// the tables' counts and sizes the per-plant passes from the frame's polygon plants; the per-plant
// pass counts each table's (`writing` false), then, after PLACE (one thread: each table's first
// place and its command), writes each plant's index in its table's run.
#include "sample_common.glsl"
#include "depth_pyramid.glsl"
#include "plant_boxes.glsl"

// Per table of plants: (first plant, end, 0, 0), then (index count, first index, base vertex, 0).
layout(std430, binding = 18) readonly buffer Tables { uvec4 tables[]; };
layout(std430, binding = 16) readonly buffer PolygonInstances { uint polygon_instances[]; };
// Per table two: its plants, then the next place in its run (a uint each, as atomics take them).
layout(std430, binding = 31) buffer LayerCounts { uint layer_counts[]; };
layout(std430, binding = 32) writeonly buffer LayerPlants { uint layer_plants[]; };
layout(std430, binding = 33) writeonly buffer LayerCommands { uint layer_commands[]; };
layout(std430, binding = 34) writeonly buffer LayerDispatch { uvec4 layer_dispatch; };
uniform uint table_count;

#if defined(START)
layout(local_size_x = 1) in;
void main() {
  for (uint t = 0u; t < 2u * table_count; ++t) layer_counts[t] = 0u;
  layer_dispatch = uvec4((polygon_count + 255u) / 256u, 1u, 1u, 0u);
}
#elif defined(PLACE)
layout(local_size_x = 1) in;
uniform uint first_command;  // the view's commands: one per table from here
void main() {
  uint first = 0u;
  for (uint t = 0u; t < table_count; ++t) {
    uvec4 mesh = tables[2u * t + 1u];
    uint plants = layer_counts[2u * t];
    uint at = 5u * (first_command + t);
    layer_commands[at] = mesh.x;
    layer_commands[at + 1u] = plants;
    layer_commands[at + 2u] = mesh.y;
    layer_commands[at + 3u] = mesh.z;
    layer_commands[at + 4u] = first;
    layer_counts[2u * t + 1u] = first;
    first += plants;
  }
}
#else
layout(local_size_x = 256) in;
uniform mat4 map_view_projection;
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

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= polygon_count) return;
  uint plant = polygon_instances[slot];
  if (shadows_nothing(map_view_projection, instances[plant].model, meshes[plant_meshes[plant].x])) return;
  uint t = table_of(plant);
  if (writing) {
    layer_plants[atomicAdd(layer_counts[2u * t + 1u], 1u)] = plant;
  } else {
    atomicAdd(layer_counts[2u * t], 1u);
  }
}
#endif
