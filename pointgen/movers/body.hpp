#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <string>
#include <vector>

namespace pointgen {

enum class PartMotion {
  fixed,
  swing,  // swings about its pivot: amplitude (radians) × sin(walk phase + phase)
  spin,   // turns about its pivot: amplitude radians per metre travelled (wheels)
};

// A rigid part of an articulated body, in the body's frame (standing on the origin, facing +Z).
struct BodyPart {
  TriangleMesh mesh;  // white-ish; the mover's colour for `color_slot` tints it
  glm::vec3 pivot{0.0f};
  glm::vec3 axis{1.0f, 0.0f, 0.0f};
  PartMotion motion = PartMotion::fixed;
  float amplitude = 0.0f;
  float phase = 0.0f;
  int color_slot = 0;  // 0, 1 or 2: which of the mover's three colours
};

// A body built from simple parts, with a walk cycle of `stride` metres.
struct Body {
  std::string name;
  std::vector<BodyPart> parts;
  float stride = 1.5f;
  float radius = 1.0f;  // of a sphere around the origin holding every pose (computed from the parts)
  bool as_points = false;  // living bodies become point samples when far; vehicles stay polygons
};

Body make_person();
Body make_cow();
Body make_car();
Body make_aeroplane();

}  // namespace pointgen
