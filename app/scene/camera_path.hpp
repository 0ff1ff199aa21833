#pragma once
#include "app/scene/scene_file.hpp"
#include "shadow/camera.hpp"

#include <string>
#include <vector>

namespace ecoview {

// A camera path: keys {"t": seconds, "position": [...], "target": [...], "up": [...] (optional)}
// with t increasing, interpolated by Catmull-Rom splines and held at either end.
class CameraPath {
 public:
  struct Key {
    double t;
    glm::vec3 position, target, up;
  };

  static CameraPath load(const InputSource& source);
  explicit CameraPath(std::vector<Key> keys) : keys_(std::move(keys)) {}

  double duration() const { return keys_.back().t; }
  // The keys as load() reads them; floats are written so that they read back exactly.
  std::string json() const;
  // The camera at time t: `base` (field of view, near, far) moved along the path.
  shadow::Camera at(double t, const shadow::Camera& base) const;

 private:
  std::vector<Key> keys_;
};

}  // namespace ecoview
