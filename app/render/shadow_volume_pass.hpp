#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/gpu_scene.hpp"
#include "shadow/light.hpp"

namespace ecoview {

// Exact shadows of polygon casters by shadow volumes with the z-fail stencil test (Carmack's
// reverse, 2000): against the depth of a drawn frame, every triangle's volume (see
// shaders/shadow_volume.geom) counts +1 behind the surface where it leaves and -1 where it
// enters, so a count of 0 means lit. The result is a mask of the frame's pixels, 1 where the light
// reaches the surface. Point splats receive through the mask but cast nothing.
class ShadowVolumePass {
 public:
  // `depth_stencil`: the frame's GL_DEPTH32F_STENCIL8 texture of width x height.
  ShadowVolumePass(int width, int height, GLuint depth_stencil);
  void render(const GpuScene& scene, const glm::mat4& view_projection, const shadow::Light& light) const;
  GLuint light_mask() const { return mask_.name(); }

 private:
  int width_, height_;
  gl::Texture mask_{GL_TEXTURE_2D};
  gl::Framebuffer framebuffer_;
  gl::Program volume_program_;
  gl::Program mask_program_;
  gl::VertexArray empty_vertex_array_;
};

}  // namespace ecoview
