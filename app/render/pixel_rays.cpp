#include "app/render/pixel_rays.hpp"

#include <cmath>
#include <optional>

namespace ecoview {

namespace {

// The point of the pixel beside (x, y) one way along `axis` or the other, whichever shows the same
// surface (a depth within 5 % of `d`, the nearer of the two); none at an edge on both sides.
std::optional<glm::vec3> beside(const Image<float>& depth, const PixelRays& rays, int x, int y, glm::ivec2 axis, float d) {
  std::optional<glm::vec3> best;
  float closest = 0.05f * d;
  for (const int side : {1, -1}) {
    const int nx = x + side * axis.x, ny = y + side * axis.y;
    if (nx < 0 || ny < 0 || nx >= depth.width || ny >= depth.height) continue;
    const float n = depth.at(nx, ny);
    if (n > 0.0f && std::abs(n - d) <= closest) {
      closest = std::abs(n - d);
      best = rays.point(nx, ny, n);
    }
  }
  return best;
}

}  // namespace

std::vector<shadow::SurfacePoint> surface_points(const Image<float>& depth, const PixelRays& rays, int step) {
  std::vector<shadow::SurfacePoint> points;
  for (int y = step / 2; y < depth.height; y += step) {
    for (int x = step / 2; x < depth.width; x += step) {
      const float d = depth.at(x, y);
      if (!(d > 0.0f)) continue;
      const std::optional<glm::vec3> across = beside(depth, rays, x, y, {1, 0}, d), down = beside(depth, rays, x, y, {0, 1}, d);
      if (!across || !down) continue;
      const glm::vec3 p = rays.point(x, y, d);
      glm::vec3 n = glm::cross(*across - p, *down - p);
      if (!(glm::length(n) > 0.0f)) continue;
      n = glm::normalize(n);
      if (glm::dot(n, rays.eye() - p) < 0.0f) n = -n;
      points.push_back({p, n});
    }
  }
  return points;
}

std::vector<glm::vec3> surface_positions(const Image<float>& depth, const PixelRays& rays, int step) {
  std::vector<glm::vec3> points;
  for (int y = step / 2; y < depth.height; y += step) {
    for (int x = step / 2; x < depth.width; x += step) {
      if (const float d = depth.at(x, y); d > 0.0f) points.push_back(rays.point(x, y, d));
    }
  }
  return points;
}

}  // namespace ecoview
