#include "shadow/aliasing.hpp"

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

glm::vec2 ndc(const glm::vec4& clip) { return glm::vec2(clip) / clip.w; }

// d(ndc.xy) along t1 and t2 at p, by central differences of `project` over a step relative to
// the distance from `eye`: one code for projective and paraboloid views.
template <class Project>
glm::mat2 jacobian(const Project& project, const glm::vec3& p, const glm::vec3& t1, const glm::vec3& t2, float step) {
  return glm::mat2((ndc(project(p + step * t1)) - ndc(project(p - step * t1))) / (2.0f * step),
                   (ndc(project(p + step * t2)) - ndc(project(p - step * t2))) / (2.0f * step));
}

glm::vec3 direction_to_light(const Light& light, const glm::vec3& p) {
  return light.type == LightType::directional ? -glm::normalize(light.direction) : glm::normalize(light.position - p);
}

}  // namespace

std::size_t view_for(const ShadowSetup& setup, const Light& light, const glm::vec3& p, int map_size) {
  switch (setup.selection) {
    case ViewSelection::single:
    case ViewSelection::screen_mask: return 0;
    case ViewSelection::first_containing: {
      const float inside = 1.0f - 2.0f * cascade_margin_texels / static_cast<float>(map_size);
      for (std::size_t i = 0; i + 1 < setup.views.size(); ++i) {
        const glm::vec4 clip = setup.views[i].clip(p);
        if (std::abs(clip.x) <= inside * clip.w && std::abs(clip.y) <= inside * clip.w && std::abs(clip.z) <= clip.w) return i;
      }
      return setup.views.size() - 1;
    }
    case ViewSelection::hemispheres: return (setup.views[0].view * glm::vec4(p, 1.0f)).z <= 0.0f ? 0 : 1;
    case ViewSelection::cube_faces: {
      const glm::vec3 d = p - light.position, a = glm::abs(d);
      if (a.x >= a.y && a.x >= a.z) return d.x >= 0 ? 0 : 1;
      if (a.y >= a.z) return d.y >= 0 ? 2 : 3;
      return d.z >= 0 ? 4 : 5;
    }
  }
  return 0;
}

float aliasing_factor(const ShadowSetup& setup, const Light& light, int map_size, const FrameView& frame,
                      const glm::vec3& p, const glm::vec3& n) {
  const glm::vec3 t1 = glm::normalize(std::abs(n.y) < 0.9f ? glm::cross(n, glm::vec3(0, 1, 0)) : glm::cross(n, glm::vec3(1, 0, 0)));
  const glm::vec3 t2 = glm::cross(n, t1);
  const ShadowView& view = setup.views[view_for(setup, light, p, map_size)];
  const glm::vec4 eye_clip = frame.view_projection * glm::vec4(p, 1.0f);
  const float step = 1e-3f * std::max(std::abs(eye_clip.w), 1e-3f);  // eye_clip.w: the view depth
  const glm::mat2 texels = 0.5f * static_cast<float>(map_size) *
                           jacobian([&](const glm::vec3& q) { return view.clip(q); }, p, t1, t2, step);
  const glm::mat2 pixels = glm::mat2(0.5f * frame.pixels.x, 0.0f, 0.0f, 0.5f * frame.pixels.y) *
                           jacobian([&](const glm::vec3& q) { return frame.view_projection * glm::vec4(q, 1.0f); }, p, t1, t2, step);
  const float size = glm::dot(texels[0], texels[0]) + glm::dot(texels[1], texels[1]);
  if (!(std::abs(glm::determinant(texels)) > 1e-6f * size)) return 1e9f;  // the light grazes the surface
  const glm::mat2 a = pixels * glm::inverse(texels);
  const float frobenius = glm::dot(a[0], a[0]) + glm::dot(a[1], a[1]);
  const float d = std::abs(glm::determinant(a));
  return 0.5f * (std::sqrt(frobenius + 2.0f * d) + std::sqrt(std::max(frobenius - 2.0f * d, 0.0f)));
}

float predicted_aliasing(const ShadowSetup& setup, const Light& light, int map_size, const FrameView& frame,
                         const std::vector<SurfacePoint>& surface, float fraction) {
  if (setup.views.empty()) return 0.0f;
  std::vector<float> factors;
  for (const SurfacePoint& s : surface) {
    if (glm::dot(s.normal, direction_to_light(light, s.position)) > 0.0f) {
      factors.push_back(aliasing_factor(setup, light, map_size, frame, s.position, s.normal));
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
