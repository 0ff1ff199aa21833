#include "app/scene/scene.hpp"

#include <algorithm>

namespace ecoview {

std::size_t LandscapeSource::group_count() const {
  std::size_t species = 0;
  for (const pointgen::LandscapeLayer& layer : spec.layers) species += layer.species.size();
  return 2 * species;
}

// Heights: the hills' fractal noise lies in [0, 1] about a relief centred on 0; the valley only cuts.
shadow::Box LandscapeSource::bounds() const {
  const float half_relief = 0.5f * spec.terrain.relief;
  const glm::vec2 half = 0.5f * spec.size + plant_reach;
  return {{-half.x, -half_relief - spec.terrain.valley_depth - plant_reach, -half.y}, {half.x, half_relief + plant_reach, half.y}};
}

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
  for (const LandscapeSource& landscape : landscapes) {
    const shadow::Box b = landscape.bounds();
    box.add(b.min);
    box.add(b.max);
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
