#version 450 core
// For the density figures: how many points land in each pixel (the nearest-point buffer reused as
// counters; run with splat_size 1).
#include "point_common.glsl"
#define VISIT(pixel, depth, point) atomicAdd(winners[pixel], 1u)
#include "point_walk.glsl"
