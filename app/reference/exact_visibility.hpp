#pragma once
#include "app/render/image.hpp"
#include "pointgen/table_list.hpp"
#include "pointgen/triangle_mesh.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"

#include <embree3/rtcore.h>

#include <vector>

namespace ecoview {

// The exact reference of `err` (docs/figures.md): from the surface point seen in each pixel, a ray to
// the light against the scene's full triangle geometry — plants as their meshes, not as their
// points — with Embree. Each mesh is one Embree scene; the instances reference it, so the whole
// ecosystem fits in memory.
class ExactVisibility {
 public:
  // The meshes and the instance tables as a renderer draws them (one geometry per instance).
  ExactVisibility(const std::vector<pointgen::TriangleMesh>& meshes, const pointgen::TableList& tables);
  ~ExactVisibility();
  ExactVisibility(const ExactVisibility&) = delete;
  ExactVisibility& operator=(const ExactVisibility&) = delete;

  // Moves the instances whose transforms changed (the tables must have the sizes given at
  // construction): moving objects posed for a frame.
  void pose(const pointgen::TableList& tables);

  // 255 where the light reaches the surface point seen in a pixel, else 0, and 255 where no
  // surface is seen (the `shadow` AOV's encoding). `depth` is the frame's linear view depth
  // (negative: no surface), drawn with `camera` (at the image's aspect). The eye ray finds the drawn surface
  // again near that depth. As in the frame's shading, a surface whose shading normal (turned to
  // the seen side) faces away from the light is unlit; else a ray from just off the surface to the
  // light decides. So the reference differs from a frame by cast shadows only. Where the eye ray
  // finds no triangle there (a point splat beside its leaf), the ray to the light starts from the
  // depth, a little towards the eye.
  Image8 trace(const shadow::Camera& camera, const shadow::Light& light, const Image<float>& depth) const;

 private:
  RTCDevice device_ = nullptr;
  std::vector<RTCScene> mesh_scenes_;  // null for a mesh without triangles
  RTCScene scene_ = nullptr;
  // Per table and instance, its instance geometry (RTC_INVALID_GEOMETRY_ID for empty meshes) and
  // the transform it has.
  std::vector<std::vector<unsigned>> geometry_ids_;
  std::vector<std::vector<glm::mat4x3>> transforms_;
  // By instance geometry ID: its mesh, and the matrix taking its object-space normals to world
  // space.
  struct Instance {
    std::uint32_t mesh = 0;
    glm::mat3 normal_matrix{1.0f};
  };
  std::vector<Instance> instances_;
  const std::vector<pointgen::TriangleMesh>& meshes_;

  void check_device() const;
  glm::vec3 geometric_normal(const RTCHit& hit) const;
  glm::vec3 shading_normal(const RTCHit& hit) const;
};

}  // namespace ecoview
