#version 450 core
// For the density figures: how many points of the front surface land in each pixel (the
// nearest-point buffer reused as counters; run with splat_size 1 after the frame's splat pass,
// whose nearest depths are still in `depths`). A point is on the front surface where its view depth
// is within `front_gap` of the nearest splat's, as a fraction of that depth.
#include "point_common.glsl"

uniform vec2 ndc_to_depth;  // (a, b) of the camera's projection: view depth = b / (ndc z + a)
uniform float front_gap;

float view_depth(uint window_depth) { return ndc_to_depth.y / (uintBitsToFloat(window_depth) * 2.0 - 1.0 + ndc_to_depth.x); }

#define VISIT(pixel, depth, point) \
  if (view_depth(depth) <= view_depth(depths[pixel]) * (1.0 + front_gap)) atomicAdd(winners[pixel], 1u)
#include "point_walk.glsl"
