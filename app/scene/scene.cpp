#include "app/scene/scene.hpp"

#include <algorithm>

namespace ecoview {

shadow::Box Scene::bounds() const {
  shadow::Box box;
  for (const pointgen::InstanceTable& group : groups) {
    const pointgen::Bounds local = meshes[group.mesh].bounds();
    if (local.empty()) continue;
    for (const glm::mat4x3& transform : group.transforms) {
      const shadow::Box placed = shadow::transformed({local.min, local.max}, transform);
      box.add(placed.min);
      box.add(placed.max);
    }
  }
  for (const Animation& a : animations) {
    const pointgen::Bounds b = a.set.bounds();
    if (!b.empty()) {
      box.add(b.min);
      box.add(b.max);
    }
  }
  return box;
}

std::size_t Scene::triangle_count() const {
  std::size_t count = 0;
  for (const pointgen::InstanceTable& group : groups) count += meshes[group.mesh].triangle_count() * group.transforms.size();
  return count;
}

bool Scene::has_point_meshes() const { return std::find(point_meshes.begin(), point_meshes.end(), true) != point_meshes.end(); }

std::size_t Scene::instance_count() const {
  std::size_t count = 0;
  for (const pointgen::InstanceTable& group : groups) count += group.transforms.size();
  return count;
}

std::size_t Scene::texture_bytes() const {
  std::size_t bytes = 0;
  for (const pointgen::TriangleMesh& mesh : meshes) bytes += mesh.texture_bytes();
  return bytes;
}

}  // namespace ecoview
