#pragma once

// How many of an object's surface samples a view needs: docs/point_density.md derives it.
namespace pointgen {

// What the count needs to know of the view: pixels per radian at the image centre,
// (image height / 2) / tan(vertical field of view / 2), and the density k in points per pixel.
struct PointDensity {
  float pixels_per_radian = 600.0f;
  float k = 1.5f;
};

// Expected number of points for k points per pixel of projected surface, for a two-sided surface
// of `area` square metres, randomly oriented, at view depth `depth` and distance `distance`
// metres from the eye: n = k · ρ² · area · distance / (2 · depth³).
float points_needed(const PointDensity& density, float area, float depth, float distance);

}  // namespace pointgen
