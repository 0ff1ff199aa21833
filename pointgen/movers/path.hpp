#pragma once
#include "pointgen/random.hpp"

#include <vector>

namespace pointgen {

// A closed polyline that movers go round at their own speed, starting at their own offset.
class LoopPath {
 public:
  explicit LoopPath(std::vector<glm::vec3> points);

  float length() const { return cumulative_.back(); }
  // Where a mover is after travelling `distance` (wrapped round the loop), and which way it faces
  // (the tangent, turned smoothly over `turn` metres around each corner).
  glm::vec3 position(float distance) const;
  glm::vec3 heading(float distance, float turn = 1.0f) const;
  const std::vector<glm::vec3>& points() const { return points_; }

 private:
  std::size_t segment(float& distance) const;  // wraps distance, returns the segment and the distance into it

  std::vector<glm::vec3> points_;
  std::vector<float> cumulative_;  // length up to the start of each segment, and the total
};

// A rectangle (x0, z0, x1, z1) on the ground plane, for regions and obstacles.
struct Rect {
  glm::vec2 min, max;
  bool contains(const glm::vec2& p) const { return p.x >= min.x && p.y >= min.y && p.x <= max.x && p.y <= max.y; }
};

// A loop through `waypoints` random points in `region`, at height `y`, whose points and legs stay
// out of `obstacles`.
LoopPath wander_loop(Random& rng, const Rect& region, const std::vector<Rect>& obstacles, int waypoints, float y);
// A circle of `radius` around `center`, counter-clockwise seen from above.
LoopPath circle_loop(const glm::vec3& center, float radius, int segments = 48);

}  // namespace pointgen
