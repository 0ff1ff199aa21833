#version 450 core
// For the density figures: how many points of the surface seen in each pixel land in it. The
// nearest-depth buffer holds that surface's view depth instead (float bits, negative where none),
// the nearest-point buffer the counts; run with splat_size 1. A point is on the surface where its
// view depth is within `surface_gap` of the surface's, as a fraction of that depth.
#include "point_common.glsl"

uniform vec2 ndc_to_depth;  // (a, b) of the camera's projection: view depth = b / (ndc z + a)
uniform float surface_gap;

float view_depth(uint window_depth) { return ndc_to_depth.y / (uintBitsToFloat(window_depth) * 2.0 - 1.0 + ndc_to_depth.x); }

bool on_surface(uint pixel, uint window_depth) {
  float surface = uintBitsToFloat(depths[pixel]);
  return surface >= 0.0 && abs(view_depth(window_depth) - surface) <= surface_gap * surface;
}

#define VISIT(pixel, depth, point) \
  if (on_surface(pixel, depth)) atomicAdd(winners[pixel], 1u)
#include "point_walk.glsl"
