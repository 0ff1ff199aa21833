#pragma once
#include <glm/glm.hpp>

#include <span>

// How many of an object's surface samples a view needs: docs/point_density.md derives it.
namespace pointgen {

// What the count needs to know of the view: pixels per radian at the image centre,
// (image height / 2) / tan(vertical field of view / 2), and the density k in points per pixel.
struct PointDensity {
  float pixels_per_radian = 600.0f;
  // The default: 2.5 keeps the holes of 2-pixel splats under 1 % on the default view
  // (docs/point_density.md, "The default k").
  float k = 2.5f;
};

// Expected number of points for k points per pixel of projected surface, for a two-sided surface
// of `area` square metres at view depth `depth` and distance `distance` metres from the eye, whose
// normals have a mean |n · v| of `facing` towards the eye (1/2 when they point every way):
// n = k · ρ² · area · facing · distance / depth³.
float points_needed(const PointDensity& density, float area, float depth, float distance, float facing = 0.5f);

// The mean of n nᵀ over surface samples' unit normals: what `facing` needs to know of a surface.
glm::mat3 normal_moments(std::span<const glm::vec3> normals);

// The mean |n · v| towards unit direction `v` of a surface with these normal moments, taken as the
// root mean square sqrt(vᵀ M v): exact for a flat surface, 0.58 instead of 0.5 for normals that
// point every way. Unknown moments (zero) give 1/2.
float facing(const glm::mat3& moments, const glm::vec3& v);

}  // namespace pointgen
