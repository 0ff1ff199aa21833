#include "app/render/volume_mask.hpp"

#include "shadow/volume_counting.hpp"

#include <algorithm>

namespace ecoview {

VolumeMask::VolumeMask(Where where, const MaskSources& sources)
    : where_(where),
      pass_(sources.size.x, sources.size.y, sources.frame.depth_stencil_texture(),
            std::ranges::any_of(sources.scene.meshes, &pointgen::TriangleMesh::masked)) {
  sources.polygons.add_adjacency(sources.scene);
  for (const pointgen::TriangleMesh& mesh : sources.scene.meshes) {
    const pointgen::Bounds bounds = mesh.bounds();
    mesh_boxes_.push_back(bounds.empty() ? shadow::Box{} : shadow::Box{bounds.min, bounds.max});
  }
}

GLuint VolumeMask::render(const MaskFrame& frame) {
  const bool z_pass = camera_outside_volumes(frame);
  const auto counting = z_pass ? ShadowVolumePass::Counting::z_pass : ShadowVolumePass::Counting::z_fail;
  if (where_ == Where::everywhere) {
    pass_.render(frame, counting);
    description_ = z_pass ? "volumes: z-pass" : "volumes: z-fail";
  } else {
    pass_.render_near_edges(frame, counting);
    description_ = z_pass ? "volumes near its edges: z-pass" : "volumes near its edges: z-fail";
  }
  return pass_.light_mask();
}

// Each caster's cell first (a box around its members' spheres), then the box of each member in it.
bool VolumeMask::camera_outside_volumes(const MaskFrame& frame) const {
  const std::vector<shadow::Plane> hull = shadow::near_plane_light_hull(frame.camera, frame.aspect, frame.light);
  for (std::size_t g = 0; g < frame.tables.size(); ++g) {
    const shadow::Box& mesh = mesh_boxes_[frame.tables[g].mesh];
    if (mesh.empty()) continue;
    for (const pointgen::InstanceCell& cell : frame.cells.by_table()[g]) {
      if (!shadow::meets(hull, {cell.min, cell.max})) continue;
      for (std::uint32_t i : cell.members) {
        if (shadow::meets(hull, shadow::transformed(mesh, frame.tables[g].transforms[i]))) return false;
      }
    }
  }
  return true;
}

}  // namespace ecoview
