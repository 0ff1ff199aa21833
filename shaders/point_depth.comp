#version 450 core
// Pass 1 of point splatting: the nearest depth per pixel.
#include "point_common.glsl"
#define VISIT(pixel, depth, point) atomicMin(depths[pixel], depth)
#include "point_walk.glsl"
