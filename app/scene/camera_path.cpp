#include "app/scene/camera_path.hpp"

#include "app/scene/scene_fields.hpp"

#include <algorithm>

namespace ecoview {
namespace {

// Cubic Hermite segment between keys i and i+1 with Catmull-Rom tangents for uneven key times.
template <class Get>
glm::vec3 spline(const std::vector<CameraPath::Key>& keys, std::size_t i, double t, Get get) {
  auto tangent = [&](std::size_t k) {
    const std::size_t a = k == 0 ? 0 : k - 1;
    const std::size_t b = std::min(k + 1, keys.size() - 1);
    return (get(keys[b]) - get(keys[a])) / static_cast<float>(keys[b].t - keys[a].t);
  };
  const auto h = static_cast<float>(keys[i + 1].t - keys[i].t);
  const auto s = static_cast<float>((t - keys[i].t) / (keys[i + 1].t - keys[i].t));
  const float s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * get(keys[i]) + (s3 - 2 * s2 + s) * h * tangent(i) +
         (-2 * s3 + 3 * s2) * get(keys[i + 1]) + (s3 - s2) * h * tangent(i + 1);
}

}  // namespace

CameraPath CameraPath::load(const InputSource& source) {
  const nlohmann::json document = parse_json(source.text, source.name);
  const JsonField root(document, source.name);
  std::vector<Key> keys;
  for (const JsonField& item : root.items(1)) {
    item.only_keys({"t", "position", "target", "up"});
    Key key{item["t"].number(0, 1e6), item["position"].vec3(), item["target"].vec3(), glm::vec3(0, 1, 0)};
    if (auto up = item.optional("up")) key.up = up->vec3();
    check_camera_frame(item, key.position, key.target, key.up);
    if (!keys.empty() && key.t <= keys.back().t) item["t"].fail("times must increase from key to key");
    keys.push_back(key);
  }
  return CameraPath(std::move(keys));
}

std::string CameraPath::json() const {
  auto array = [](const glm::vec3& v) { return nlohmann::ordered_json::array({v.x, v.y, v.z}); };
  nlohmann::ordered_json keys = nlohmann::ordered_json::array();
  for (const Key& key : keys_) {
    keys.push_back({{"t", key.t}, {"position", array(key.position)}, {"target", array(key.target)}, {"up", array(key.up)}});
  }
  std::string text = "[\n";
  for (std::size_t i = 0; i < keys.size(); ++i) text += "  " + keys[i].dump() + (i + 1 < keys.size() ? ",\n" : "\n");
  return text + "]\n";
}

shadow::Camera CameraPath::at(double t, const shadow::Camera& base) const {
  shadow::Camera camera = base;
  auto place_at = [&](const Key& key) {
    camera.position = key.position;
    camera.target = key.target;
    camera.up = key.up;
  };
  if (keys_.size() == 1 || t <= keys_.front().t) {
    place_at(keys_.front());
  } else if (t >= keys_.back().t) {
    place_at(keys_.back());
  } else {
    const auto next = std::upper_bound(keys_.begin(), keys_.end(), t, [](double v, const Key& k) { return v < k.t; });
    const auto i = static_cast<std::size_t>(next - keys_.begin() - 1);
    camera.position = spline(keys_, i, t, [](const Key& k) { return k.position; });
    camera.target = spline(keys_, i, t, [](const Key& k) { return k.target; });
    camera.up = spline(keys_, i, t, [](const Key& k) { return k.up; });
  }
  // Between valid keys a spline can pass through a degenerate frame; keep the camera valid.
  if (glm::length(camera.target - camera.position) < 1e-6f) camera.target = camera.position + base.forward();
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  // Between opposite up vectors the blend passes through zero: fall back to a valid one.
  if (!(glm::length(glm::cross(forward, camera.up)) >= 1e-4f * glm::length(camera.up)) || glm::length(camera.up) < 1e-6f) {
    camera.up = std::abs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
  }
  camera.up = glm::normalize(camera.up);
  return camera;
}

}  // namespace ecoview
