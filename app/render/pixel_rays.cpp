#include "app/render/pixel_rays.hpp"

#include <cmath>

namespace ecoview {

std::vector<shadow::SurfacePoint> surface_points(const Image<float>& depth, const PixelRays& rays, int step) {
  std::vector<shadow::SurfacePoint> points;
  for (int y = step / 2; y + 1 < depth.height; y += step) {
    for (int x = step / 2; x + 1 < depth.width; x += step) {
      const float d = depth.at(x, y), dx = depth.at(x + 1, y), dy = depth.at(x, y + 1);
      if (!(d > 0.0f && dx > 0.0f && dy > 0.0f) || std::abs(dx - d) > 0.05f * d || std::abs(dy - d) > 0.05f * d) continue;
      const glm::vec3 p = rays.point(x, y, d);
      glm::vec3 n = glm::cross(rays.point(x + 1, y, dx) - p, rays.point(x, y + 1, dy) - p);
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
