#include "shadow/aliasing.hpp"

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

glm::vec2 ndc(const glm::vec4& clip) { return glm::vec2(clip) / clip.w; }

// d(ndc.xy) along t1 and t2 at p, by central differences of `project` over `step` (paraboloid views).
template <class Project>
glm::mat2 jacobian(const Project& project, const glm::vec3& p, const glm::vec3& t1, const glm::vec3& t2, float step) {
  return glm::mat2((ndc(project(p + step * t1)) - ndc(project(p - step * t1))) / (2.0f * step),
                   (ndc(project(p + step * t2)) - ndc(project(p - step * t2))) / (2.0f * step));
}

// The same for a projective matrix, exactly: the derivative of xy / w.
glm::mat2 jacobian(const glm::mat4& m, const glm::vec3& p, const glm::vec3& t1, const glm::vec3& t2) {
  const glm::vec4 c = m * glm::vec4(p, 1.0f);
  const auto along = [&](const glm::vec3& t) {
    const glm::vec4 dc = m * glm::vec4(t, 0.0f);
    return (glm::vec2(dc) * c.w - glm::vec2(c) * dc.w) / (c.w * c.w);
  };
  return glm::mat2(along(t1), along(t2));
}

glm::vec3 direction_to_light(const Light& light, const glm::vec3& p) {
  return light.type == LightType::directional ? -glm::normalize(light.direction) : glm::normalize(light.position - p);
}

// A setup with its projective views' world → clip matrices multiplied out once, for the many
// points of a prediction.
class Projections {
 public:
  explicit Projections(const ShadowSetup& setup) : setup_(setup) {
    for (const ShadowView& view : setup.views) matrices_.push_back(view.view_projection());
  }

  glm::vec4 clip(std::size_t view, const glm::vec3& p) const {
    return setup_.views[view].paraboloid ? setup_.views[view].clip(p) : matrices_[view] * glm::vec4(p, 1.0f);
  }

  std::size_t view_for(const Light& light, const glm::vec3& p, int map_size) const {
    switch (setup_.selection) {
      case ViewSelection::single:
      case ViewSelection::screen_mask: return 0;
      case ViewSelection::first_containing: {
        const float inside = 1.0f - 2.0f * cascade_margin_texels / static_cast<float>(map_size);
        for (std::size_t i = 0; i + 1 < setup_.views.size(); ++i) {
          const glm::vec4 c = clip(i, p);
          if (std::abs(c.x) <= inside * c.w && std::abs(c.y) <= inside * c.w && std::abs(c.z) <= c.w) return i;
        }
        return setup_.views.size() - 1;
      }
      case ViewSelection::hemispheres: return (setup_.views[0].view * glm::vec4(p, 1.0f)).z <= 0.0f ? 0 : 1;
      case ViewSelection::cube_faces: {
        const glm::vec3 d = p - light.position, a = glm::abs(d);
        if (a.x >= a.y && a.x >= a.z) return d.x >= 0 ? 0 : 1;
        if (a.y >= a.z) return d.y >= 0 ? 2 : 3;
        return d.z >= 0 ? 4 : 5;
      }
    }
    return 0;
  }

  float aliasing_factor(const Light& light, int map_size, const FrameView& frame, const glm::vec3& p, const glm::vec3& n) const {
    const glm::vec3 t1 = glm::normalize(std::abs(n.y) < 0.9f ? glm::cross(n, glm::vec3(0, 1, 0)) : glm::cross(n, glm::vec3(1, 0, 0)));
    const glm::vec3 t2 = glm::cross(n, t1);
    const std::size_t view = view_for(light, p, map_size);
    // A paraboloid view by central differences, over a step relative to the view depth (the w of
    // the frame's clip coordinates).
    const float step = 1e-3f * std::max(std::abs((frame.view_projection * glm::vec4(p, 1.0f)).w), 1e-3f);
    const glm::mat2 to_map = setup_.views[view].paraboloid
                                 ? jacobian([&](const glm::vec3& q) { return clip(view, q); }, p, t1, t2, step)
                                 : jacobian(matrices_[view], p, t1, t2);
    const glm::mat2 texels = 0.5f * static_cast<float>(map_size) * to_map;
    const glm::mat2 pixels = glm::mat2(0.5f * frame.pixels.x, 0.0f, 0.0f, 0.5f * frame.pixels.y) * jacobian(frame.view_projection, p, t1, t2);
    const float size = glm::dot(texels[0], texels[0]) + glm::dot(texels[1], texels[1]);
    if (!(std::abs(glm::determinant(texels)) > 1e-6f * size)) return 1e9f;  // the light grazes the surface
    const glm::mat2 a = pixels * glm::inverse(texels);
    const float frobenius = glm::dot(a[0], a[0]) + glm::dot(a[1], a[1]);
    const float d = std::abs(glm::determinant(a));
    return 0.5f * (std::sqrt(frobenius + 2.0f * d) + std::sqrt(std::max(frobenius - 2.0f * d, 0.0f)));
  }

 private:
  const ShadowSetup& setup_;
  std::vector<glm::mat4> matrices_;  // per view; unused for paraboloid views
};

}  // namespace

std::size_t view_for(const ShadowSetup& setup, const Light& light, const glm::vec3& p, int map_size) {
  return Projections(setup).view_for(light, p, map_size);
}

float aliasing_factor(const ShadowSetup& setup, const Light& light, int map_size, const FrameView& frame,
                      const glm::vec3& p, const glm::vec3& n) {
  return Projections(setup).aliasing_factor(light, map_size, frame, p, n);
}

float predicted_aliasing(const ShadowSetup& setup, const Light& light, int map_size, const FrameView& frame,
                         const std::vector<SurfacePoint>& surface, float fraction) {
  if (setup.views.empty()) return 0.0f;
  const Projections projections(setup);
  std::vector<float> factors;
  for (const SurfacePoint& s : surface) {
    if (glm::dot(s.normal, direction_to_light(light, s.position)) > 0.0f) {
      factors.push_back(projections.aliasing_factor(light, map_size, frame, s.position, s.normal));
    }
  }
  return percentile(std::move(factors), fraction);
}

float percentile(std::vector<float> values, float fraction) {
  if (values.empty()) return 0.0f;
  const auto at = values.begin() + static_cast<std::ptrdiff_t>(static_cast<double>(fraction) * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

}  // namespace shadow
