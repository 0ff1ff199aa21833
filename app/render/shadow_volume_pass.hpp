#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/gpu_scene.hpp"
#include "shadow/light.hpp"

namespace ecoview {

// Exact shadows of polygon casters by stencil shadow volumes extruded from silhouette edges
// (shaders/shadow_volume.geom), counted against the depth of a drawn frame so that a count of 0
// means lit. z-pass (Heidmann 1991): faces in front of the surface, +1 entering and -1 leaving; it
// needs no far caps, but holds only where the camera stands in no volume. z-fail (Carmack's
// reverse, 2000): faces behind the surface, +1 leaving and -1 entering, with far caps; it holds
// everywhere. The result is a mask of the frame's pixels, 1 where the light reaches the surface.
// Point splats receive through the mask but cast nothing.
class ShadowVolumePass {
 public:
  // `depth_stencil`: the frame's GL_DEPTH32F_STENCIL8 texture of width x height.
  ShadowVolumePass(int width, int height, GLuint depth_stencil);
  enum class Counting { z_pass, z_fail };
  // `scene` with its neighbours found (GpuScene::add_adjacency).
  void render(const GpuScene& scene, const glm::mat4& view_projection, const shadow::Light& light, Counting counting) const;
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
