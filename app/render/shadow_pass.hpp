#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/gpu_scene.hpp"

namespace ecoview {

// Renders the scene's depth as the light sees it into a square depth texture set up for hardware
// depth comparison (sampler2DShadow, bilinear PCF), with slope-scaled polygon offset against acne.
class ShadowPass {
 public:
  explicit ShadowPass(int size);
  void render(const GpuScene& scene, const glm::mat4& light_view_projection) const;
  GLuint depth_texture() const { return depth_.name(); }
  int size() const { return size_; }

 private:
  int size_;
  gl::Texture depth_{GL_TEXTURE_2D};
  gl::Framebuffer framebuffer_;
  gl::Program program_;
};

}  // namespace ecoview
