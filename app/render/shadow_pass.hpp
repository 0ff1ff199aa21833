#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/gpu_scene.hpp"
#include "app/render/image.hpp"
#include "app/render/render_settings.hpp"
#include "shadow/shadow_setup.hpp"

namespace ecoview {

// Sets a depth texture up as the frame's lighting samples shadow maps: hardware comparisons
// (sampler2DArrayShadow), filtered bilinearly, and depth 1 (lit) off its edges.
void make_comparable(GLuint depth_texture);

// Renders the scene's depth as the light sees it, one layer of a square depth-texture array per
// view of the shadow setup, set up for hardware depth comparison (sampler2DArrayShadow, bilinear
// PCF), with slope-scaled polygon offset against acne. Paraboloid views tessellate the scene.
class ShadowPass {
 public:
  // `surface_textures`: the scene has textures or alpha masks (GpuScene::has_surface_textures),
  // and masks cut its surfaces out of the map.
  ShadowPass(int size, DepthBias bias, ShadowDepth depth, bool surface_textures);
  // Draws one view of the setup into its layer.
  // With `plants`, also those polygon plants of a GPU sampler.
  void render(const GpuScene& scene, const shadow::ShadowSetup& setup, int layer, const GpuScene::PlantDraws* plants = nullptr);
  // Makes room for `layers` layers (the views' and others after them) before any is drawn: a
  // larger texture drops what the layers held.
  void reserve_layers(int layers);
  // Sets a layer to depth 1 (nothing drawn), for casters drawn there without polygons.
  void clear_layer(int layer);
  GLuint depth_texture() const { return depth_.name(); }
  GLenum depth_format() const { return format_; }  // the texture's internal format
  // One layer's depths, window depth 0 (near) to 1 (far), rows from the top.
  Image<float> read_layer(int layer) const;
  int size() const { return size_; }

 private:
  void allocate(int layers);

  int size_;
  DepthBias bias_;
  GLenum format_;
  int layers_ = 0;
  gl::Texture depth_{GL_TEXTURE_2D_ARRAY};
  gl::Framebuffer framebuffer_;
  // Each for GpuScene's groups, and for the GPU sampler's polygon plants (shaders/instance.glsl).
  gl::Program program_, plant_program_;
  gl::Program paraboloid_program_, plant_paraboloid_program_;
};

}  // namespace ecoview
