#version 450 core
// Pass 2 of point splatting: per pixel, the point with the nearest depth (the lowest index among
// equals, so the result does not depend on thread order).
#include "point_common.glsl"
#define VISIT(pixel, depth, point) if (depths[pixel] == depth) atomicMin(winners[pixel], point)
#include "point_walk.glsl"
