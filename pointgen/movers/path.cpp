#include "pointgen/movers/path.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace pointgen {
namespace {

// Whether the segment from a to b touches the rectangle (Liang-Barsky clipping).
bool segment_hits(const glm::vec2& a, const glm::vec2& b, const Rect& r) {
  float t0 = 0.0f, t1 = 1.0f;
  const glm::vec2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0f) {
      if (a[axis] < r.min[axis] || a[axis] > r.max[axis]) return false;
      continue;
    }
    float enter = (r.min[axis] - a[axis]) / d[axis], leave = (r.max[axis] - a[axis]) / d[axis];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

LoopPath::LoopPath(std::vector<glm::vec3> points) : points_(std::move(points)) {
  cumulative_.push_back(0.0f);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    cumulative_.push_back(cumulative_.back() + glm::distance(points_[i], points_[(i + 1) % points_.size()]));
  }
}

std::size_t LoopPath::segment(float& distance) const {
  distance = std::fmod(distance, length());
  if (distance < 0.0f) distance += length();
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), distance);
  const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - cumulative_.begin() - 1));
  const std::size_t s = std::min(i, points_.size() - 1);
  distance -= cumulative_[s];
  return s;
}

glm::vec3 LoopPath::position(float distance) const {
  const std::size_t s = segment(distance);
  const glm::vec3& a = points_[s];
  const glm::vec3& b = points_[(s + 1) % points_.size()];
  const float l = glm::distance(a, b);
  return l > 0.0f ? a + (b - a) * (distance / l) : a;
}

glm::vec3 LoopPath::heading(float distance, float turn) const {
  const glm::vec3 d = position(distance + 0.5f * turn) - position(distance - 0.5f * turn);
  return glm::length(d) > 1e-6f ? glm::normalize(d) : glm::vec3(1, 0, 0);
}

LoopPath wander_loop(Random& rng, const Rect& region, const std::vector<Rect>& obstacles, int waypoints, float y) {
  auto blocked = [&](const glm::vec2& p) {
    return std::any_of(obstacles.begin(), obstacles.end(), [&](const Rect& r) { return r.contains(p); });
  };
  std::vector<glm::vec2> points;
  for (int tries = 0; static_cast<int>(points.size()) < waypoints && tries < 200 * waypoints; ++tries) {
    const glm::vec2 p(rng.uniform(region.min.x, region.max.x), rng.uniform(region.min.y, region.max.y));
    const bool leg_clear = points.empty() || std::none_of(obstacles.begin(), obstacles.end(),
                                                          [&](const Rect& r) { return segment_hits(points.back(), p, r); });
    if (!blocked(p) && leg_clear) points.push_back(p);
  }
  // Close the loop only where its last leg is clear; otherwise walk back along the way out.
  const bool closes = points.size() < 2 || std::none_of(obstacles.begin(), obstacles.end(),
                                                        [&](const Rect& r) { return segment_hits(points.back(), points.front(), r); });
  if (!closes) {
    for (std::size_t i = points.size() - 1; i-- > 1;) points.push_back(points[i]);
  }
  if (points.empty()) points.push_back(0.5f * (region.min + region.max));
  if (points.size() == 1) points.push_back(points[0] + glm::vec2(0.5f, 0.0f));
  std::vector<glm::vec3> loop;
  for (const glm::vec2& p : points) loop.emplace_back(p.x, y, p.y);
  return LoopPath(std::move(loop));
}

LoopPath circle_loop(const glm::vec3& center, float radius, int segments) {
  std::vector<glm::vec3> points;
  for (int i = 0; i < segments; ++i) {
    const float a = glm::two_pi<float>() * static_cast<float>(i) / static_cast<float>(segments);
    points.push_back(center + radius * glm::vec3(std::cos(a), 0.0f, -std::sin(a)));
  }
  return LoopPath(std::move(points));
}

}  // namespace pointgen
