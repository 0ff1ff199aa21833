#include "app/render/shadow_pass.hpp"

#include "app/gl/shader_program.hpp"
#include "app/render/gpu_sampler.hpp"

namespace ecoview {
namespace {

// glPolygonOffset(factor, units): the factor scales with the depth slope of each triangle, which
// removes acne on surfaces the light grazes; the units add a few depth steps everywhere.
constexpr float offset_factor = 2.0f;
constexpr float offset_units = 4.0f;

void draw_chosen(const GpuScene& scene, const GpuSampler* chosen, GLenum mode) {
  if (chosen) scene.draw_chosen(*chosen, 0, chosen->band_count(), mode);
}

}  // namespace

ShadowPass::ShadowPass(int size)
    : size_(size),
      program_(gl::build_program({"shadow_depth.vert", "shadow_depth.frag"})),
      paraboloid_program_(gl::build_program({"world_position.vert", "shadow_paraboloid.tesc", "shadow_paraboloid.tese",
                                             "shadow_depth.frag"})) {
  allocate(1);
}

// Texture storage is immutable: a setup with more views than allocated gets a new texture.
void ShadowPass::allocate(int layers) {
  depth_ = gl::Texture(GL_TEXTURE_2D_ARRAY);
  layers_ = layers;
  const GLuint t = depth_.name();
  glTextureStorage3D(t, 1, GL_DEPTH_COMPONENT32F, size_, size_, layers);
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(t, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  // Outside the map nothing was rendered: depth 1 there reads as lit.
  glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTextureParameterfv(t, GL_TEXTURE_BORDER_COLOR, border);
  glNamedFramebufferDrawBuffer(framebuffer_.name(), GL_NONE);
  glNamedFramebufferReadBuffer(framebuffer_.name(), GL_NONE);
}

void ShadowPass::render(const GpuScene& scene, const shadow::ShadowSetup& setup, int layer, const GpuSampler* chosen) {
  if (static_cast<int>(setup.views.size()) > layers_) allocate(static_cast<int>(setup.views.size()));
  const GLuint fb = framebuffer_.name();
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glViewport(0, 0, size_, size_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // planes are single-sided but cast shadows from both sides
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(offset_factor, offset_units);
  glNamedFramebufferTextureLayer(fb, GL_DEPTH_ATTACHMENT, depth_.name(), 0, layer);
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
  const shadow::ShadowView& view = setup.views[static_cast<std::size_t>(layer)];
  if (view.paraboloid) {
    glUseProgram(paraboloid_program_.name());
    gl::set_uniform(paraboloid_program_, "light_view", view.view);
    gl::set_uniform(paraboloid_program_, "paraboloid", view.paraboloid_parameters());
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    glEnable(GL_CLIP_DISTANCE0);
    scene.draw(GL_PATCHES);
    draw_chosen(scene, chosen, GL_PATCHES);
    glDisable(GL_CLIP_DISTANCE0);
  } else {
    glUseProgram(program_.name());
    gl::set_uniform(program_, "light_view_projection", view.view_projection());
    scene.draw();
    draw_chosen(scene, chosen, GL_TRIANGLES);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
}

Image<float> ShadowPass::read_layer(int layer) const {
  std::vector<float> bottom_up(static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_));
  glGetTextureSubImage(depth_.name(), 0, 0, 0, layer, size_, size_, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                       static_cast<GLsizei>(bottom_up.size() * sizeof(float)), bottom_up.data());
  return from_bottom_up(size_, size_, 1, bottom_up);
}

}  // namespace ecoview
