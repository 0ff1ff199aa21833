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
  PixelRays(const shadow::Camera& camera, int width, int height)
      : eye_(camera.position),
        forward_(camera.forward()),
        to_world_(glm::inverse(camera.projection(static_cast<float>(width) / static_cast<float>(height)) * camera.view())),
        width_(width),
        height_(height) {}

  glm::vec3 eye() const { return eye_; }
  glm::vec3 direction(int x, int y) const {
    const glm::vec2 ndc((2.0f * static_cast<float>(x) + 1.0f) / static_cast<float>(width_) - 1.0f,
                        1.0f - (2.0f * static_cast<float>(y) + 1.0f) / static_cast<float>(height_));
    const glm::vec4 far_point = to_world_ * glm::vec4(ndc, 1.0f, 1.0f);
    return glm::normalize(glm::vec3(far_point) / far_point.w - eye_);
  }
  // Distance along `direction` to the point at linear view depth `depth`.
  float distance(const glm::vec3& direction, float depth) const { return depth / glm::dot(direction, forward_); }
  glm::vec3 point(int x, int y, float depth) const {
    const glm::vec3 d = direction(x, y);
    return eye_ + d * distance(d, depth);
  }

 private:
  glm::vec3 eye_, forward_;
  glm::mat4 to_world_;
  int width_, height_;
};

// Surface points of a frame (its linear view depth) on a grid of every `step`-th pixel, with
// normals from the neighbouring pixels' points turned to the eye: across and down, from whichever
// neighbour on each axis shows the same surface (so a pixel at a silhouette keeps its normal from
// the side it belongs to); none where neither does on an axis (a sliver thinner than a pixel).
std::vector<shadow::SurfacePoint> surface_points(const Image<float>& depth, const PixelRays& rays, int step);
// The points of every `step`-th pixel that shows a surface, edges and all.
std::vector<glm::vec3> surface_positions(const Image<float>& depth, const PixelRays& rays, int step);

}  // namespace ecoview
