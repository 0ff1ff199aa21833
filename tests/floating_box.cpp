#include "floating_box.hpp"

#include "app/scene/scene_file.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace ecoview::test {
namespace {

std::string vec(const glm::vec3& v) {
  std::ostringstream s;
  s.precision(9);
  s << "[" << v.x << ", " << v.y << ", " << v.z << "]";
  return s.str();
}

// Smallest t >= 0 with origin + t * dir inside the box, or a negative number.
float hit_box(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& lo, const glm::vec3& hi) {
  float t0 = 0.0f, t1 = std::numeric_limits<float>::max();
  for (int a = 0; a < 3; ++a) {
    if (std::abs(dir[a]) < 1e-12f) {
      if (origin[a] < lo[a] || origin[a] > hi[a]) return -1.0f;
      continue;
    }
    float ta = (lo[a] - origin[a]) / dir[a], tb = (hi[a] - origin[a]) / dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return -1.0f;
  }
  return t0;
}

enum class Truth : std::uint8_t { not_plane, lit, shadowed };

Truth plane_truth(const FloatingBox& s, const glm::vec3& p) {
  const shadow::Light& light = s.light;
  glm::vec3 to_light;
  float reach = std::numeric_limits<float>::max();
  if (light.type == shadow::LightType::directional) {
    to_light = -glm::normalize(light.direction);
  } else {
    to_light = light.position - p;
    reach = glm::length(to_light);
    to_light /= reach;
  }
  if (to_light.y <= 0.0f) return Truth::shadowed;  // the light is below the plane
  if (light.type == shadow::LightType::spot &&
      glm::dot(-to_light, glm::normalize(light.direction)) < std::cos(glm::radians(light.cone_deg))) {
    return Truth::shadowed;  // outside the cone: no light
  }
  const float t = hit_box(p, to_light, s.box_min, s.box_max);
  return t >= 0.0f && t < reach ? Truth::shadowed : Truth::lit;
}

float uniform(pointgen::Random& rng, float lo, float hi) { return rng.uniform(lo, hi); }

}  // namespace

std::string FloatingBox::scene_json() const {
  std::ostringstream s;
  s.precision(9);
  s << R"({"camera": {"position": )" << vec(camera.position) << R"(, "target": )" << vec(camera.target)
    << R"(, "fov_y_deg": )" << camera.fov_y_deg << R"(, "near": )" << camera.near << R"(, "far": )" << camera.far
    << "},\n \"lights\": [";
  switch (light.type) {
    case shadow::LightType::directional:
      s << R"({"type": "directional", "direction": )" << vec(light.direction) << "}";
      break;
    case shadow::LightType::point:
      s << R"({"type": "point", "position": )" << vec(light.position) << "}";
      break;
    case shadow::LightType::spot:
      s << R"({"type": "spot", "position": )" << vec(light.position) << R"(, "direction": )" << vec(light.direction)
        << R"(, "cone_deg": )" << light.cone_deg << "}";
      break;
  }
  s << "],\n \"objects\": [" << R"({"type": "plane", "center": [0, 0, 0], "size": [)" << 2 * plane_half_size << ", "
    << 2 * plane_half_size << "]},\n  " << R"({"type": "box", "min": )" << vec(box_min) << R"(, "max": )"
    << vec(box_max) << "}]}\n";
  return s.str();
}

Scene FloatingBox::scene() const {
  return load_scene({"floating_box.json", scene_json(), [](const std::string&) { return std::nullopt; }});
}

FloatingBox random_floating_box(pointgen::Random& rng, shadow::LightType type) {
  FloatingBox s;
  const glm::vec3 size(uniform(rng, 0.5f, 3.0f), uniform(rng, 0.3f, 2.0f), uniform(rng, 0.5f, 3.0f));
  const glm::vec3 center(uniform(rng, -3.0f, 3.0f), uniform(rng, 0.6f, 3.0f) + 0.5f * size.y, uniform(rng, -3.0f, 3.0f));
  s.box_min = center - 0.5f * size;
  s.box_max = center + 0.5f * size;

  const float azimuth = uniform(rng, 0.0f, glm::two_pi<float>());
  const float elevation = glm::radians(uniform(rng, 30.0f, 80.0f));
  const glm::vec3 towards_light(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                                std::cos(elevation) * std::sin(azimuth));
  s.light.type = type;
  s.light.direction = -towards_light;
  const glm::vec3 ground_below(center.x, 0.0f, center.z);
  glm::vec3 shadow_center = ground_below;  // roughly where the shadow falls
  if (type != shadow::LightType::directional) {
    s.light.position = center + towards_light * uniform(rng, 4.0f, 12.0f);
    s.light.direction = glm::normalize(ground_below - s.light.position);
    s.light.cone_deg = uniform(rng, 35.0f, 55.0f);
  }
  const float along = center.y / towards_light.y;  // box centre to the plane along the light
  shadow_center = ground_below - glm::vec3(towards_light.x, 0.0f, towards_light.z) * along;

  // From the side the light goes to, so the box does not hide its own shadow.
  const float camera_azimuth = azimuth + glm::pi<float>() + glm::radians(uniform(rng, -100.0f, 100.0f));
  const float camera_elevation = glm::radians(uniform(rng, 20.0f, 60.0f));
  const float distance = uniform(rng, 6.0f, 14.0f);
  s.camera.target = 0.5f * (shadow_center + center);
  s.camera.position = s.camera.target + distance * glm::vec3(std::cos(camera_elevation) * std::cos(camera_azimuth),
                                                             std::sin(camera_elevation),
                                                             std::cos(camera_elevation) * std::sin(camera_azimuth));
  s.camera.fov_y_deg = uniform(rng, 40.0f, 60.0f);
  s.camera.near = 0.1f;
  s.camera.far = 100.0f;
  return s;
}

TruthComparison compare_with_truth(const FloatingBox& s, const Image8& aov, int margin) {
  const int w = aov.width, h = aov.height;
  const glm::mat4 inverse = glm::inverse(s.camera.projection(static_cast<float>(w) / static_cast<float>(h)) * s.camera.view());
  std::vector<Truth> truth(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), Truth::not_plane);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const glm::vec2 ndc(2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(w) - 1.0f,
                          1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
      const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f);
      const glm::vec4 b = inverse * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 origin = glm::vec3(a) / a.w;
      const glm::vec3 dir = glm::vec3(b) / b.w - origin;
      if (dir.y >= 0.0f) continue;
      const float t_plane = -origin.y / dir.y;
      if (t_plane > 1.0f) continue;  // beyond the far plane
      const float t_box = hit_box(origin, dir, s.box_min, s.box_max);
      if (t_box >= 0.0f && t_box < t_plane) continue;
      const glm::vec3 p = origin + t_plane * dir;
      if (std::abs(p.x) > s.plane_half_size || std::abs(p.z) > s.plane_half_size) continue;
      truth[static_cast<std::size_t>(y * w + x)] = plane_truth(s, p);
    }
  }
  TruthComparison result;
  result.mismatches = {w, h, 3, std::vector<std::uint8_t>(static_cast<std::size_t>(w * h * 3), 0)};
  for (int y = margin; y < h - margin; ++y) {
    for (int x = margin; x < w - margin; ++x) {
      const Truth t = truth[static_cast<std::size_t>(y * w + x)];
      if (t == Truth::not_plane) continue;
      bool uniform_window = true;
      for (int dy = -margin; dy <= margin && uniform_window; ++dy) {
        for (int dx = -margin; dx <= margin; ++dx) {
          if (truth[static_cast<std::size_t>((y + dy) * w + x + dx)] != t) {
            uniform_window = false;
            break;
          }
        }
      }
      if (!uniform_window) continue;
      const bool rendered_shadowed = aov.at(x, y) < 128;
      const glm::u8vec3 mark = rendered_shadowed == (t == Truth::shadowed) ? glm::u8vec3(128)
                               : rendered_shadowed                     ? glm::u8vec3(0, 0, 255)
                                                                        : glm::u8vec3(255, 0, 0);
      std::copy_n(&mark.x, 3, &result.mismatches.samples[static_cast<std::size_t>((y * w + x) * 3)]);
      if (t == Truth::shadowed) {
        ++result.shadowed;
        result.shadowed_agreeing += rendered_shadowed;
      } else {
        ++result.lit;
        result.lit_agreeing += !rendered_shadowed;
      }
    }
  }
  return result;
}

}  // namespace ecoview::test
