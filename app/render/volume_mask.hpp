#pragma once
#include "app/render/mask_technique.hpp"
#include "app/render/shadow_volume_pass.hpp"
#include "shadow/box.hpp"

#include <string>
#include <vector>

namespace ecoview {

// Shadow volumes as a mask technique: `volumes` counts them over the whole frame; `hybrid` (Chan
// and Durand 2004) only near the edges of the shadows its map drew, where the map's filtered test
// was neither all lit nor all shadowed. Each frame counts z-pass where no caster stands between
// the camera's near plane and the light, z-fail elsewhere (shadow/volume_counting.hpp).
class VolumeMask : public MaskTechnique {
 public:
  enum class Where { everywhere, near_map_edges };
  VolumeMask(Where where, const MaskSources& sources);
  GLuint render(const MaskFrame& frame) override;
  const std::string& description() const override { return description_; }
  const char* stage() const override { return "shadow volumes"; }
  bool casts_from_frame_polygons() const override { return true; }
  bool made_on_cpu() const override { return false; }

 private:
  // Whether no caster meets the hull of the near plane and the light.
  bool camera_outside_volumes(const MaskFrame& frame) const;

  Where where_;
  ShadowVolumePass pass_;
  std::vector<shadow::Box> mesh_boxes_;  // each mesh's bounds
  std::string description_;
};

}  // namespace ecoview
