#pragma once
#include "app/render/mask_technique.hpp"

#include <functional>
#include <string>

namespace ecoview {

// The exact reference as a mask technique: rays from each pixel's surface to the light against
// every triangle (ExactVisibility, on the CPU), uploaded as the frame's mask.
class ReferenceMask : public MaskTechnique {
 public:
  explicit ReferenceMask(const MaskSources& sources);
  GLuint render(const MaskFrame& frame) override;
  const std::string& description() const override { return description_; }
  const char* stage() const override { return "reference mask"; }
  bool casts_from_frame_polygons() const override { return false; }
  bool made_on_cpu() const override { return true; }

 private:
  std::function<ExactVisibility&()> exact_;
  gl::Texture mask_{GL_TEXTURE_2D};  // R8, the lit pixels
  std::string description_ = "reference";
};

}  // namespace ecoview
