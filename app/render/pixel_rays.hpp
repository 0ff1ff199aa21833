#pragma once
#include "app/render/image.hpp"
#include "shadow/aliasing.hpp"
#include "shadow/camera.hpp"

#include <glm/glm.hpp>

namespace ecoview {

// The rays from the eye through the pixel centres of a frame (rows from the top), and where a
// ray meets the surface the frame drew at a linear view depth.
class PixelRays {
 public:
  PixelRays(const shadow::Camera& camera, int width, int height) : eye_(camera.position), forward_(camera.forward()) {
    // A ray's direction, up to a positive scale, is far.xyz - eye * far.w for the far plane's
    // point `far` in homogeneous world coordinates: affine in the pixel's coordinates, so three
    // corners of the grid give every pixel's without a matrix product each.
    const glm::mat4 to_world = glm::inverse(camera.projection(static_cast<float>(width) / static_cast<float>(height)) * camera.view());
    const auto at = [&](float x, float y) {
      const glm::vec4 far = to_world * glm::vec4((2.0f * x + 1.0f) / static_cast<float>(width) - 1.0f,
                                                 1.0f - (2.0f * y + 1.0f) / static_cast<float>(height), 1.0f, 1.0f);
      return glm::vec3(far) - eye_ * far.w;
    };
    origin_ = at(0.0f, 0.0f);
    across_ = at(1.0f, 0.0f) - origin_;
    down_ = at(0.0f, 1.0f) - origin_;
  }

  glm::vec3 eye() const { return eye_; }
  glm::vec3 direction(int x, int y) const { return glm::normalize(unscaled(x, y)); }
  // Distance along `direction` to the point at linear view depth `depth`.
  float distance(const glm::vec3& direction, float depth) const { return depth / glm::dot(direction, forward_); }
  glm::vec3 point(int x, int y, float depth) const {
    const glm::vec3 d = unscaled(x, y);
    return eye_ + d * distance(d, depth);
  }

 private:
  glm::vec3 unscaled(int x, int y) const { return origin_ + static_cast<float>(x) * across_ + static_cast<float>(y) * down_; }
  glm::vec3 eye_, forward_;
  glm::vec3 origin_{0.0f}, across_{0.0f}, down_{0.0f};  // the unscaled direction of pixel (0, 0) and its steps
};

// Surface points of a frame (its linear view depth) on a grid of every `step`-th pixel, with
// normals from the neighbouring pixels' points turned to the eye: across and down, from whichever
// neighbour on each axis shows the same surface (so a pixel at a silhouette keeps its normal from
// the side it belongs to); none where neither does on an axis (a sliver thinner than a pixel).
std::vector<shadow::SurfacePoint> surface_points(const Image<float>& depth, const PixelRays& rays, int step);
// The points of every `step`-th pixel that shows a surface, edges and all.
std::vector<glm::vec3> surface_positions(const Image<float>& depth, const PixelRays& rays, int step);

}  // namespace ecoview
