#include "app/render/silhouette_pass.hpp"

#include "app/gl/shader_program.hpp"
#include "shadow/post_perspective.hpp"

namespace ecoview {

SilhouettePass::SilhouettePass(int size)
    : size_(size), edges_({"world_position.vert", "silhouette_edges.geom", "silhouette_point.frag"}) {
  allocate(1);
}

// Texture storage is immutable: a setup with more views than allocated gets a new texture.
void SilhouettePass::allocate(int layers) {
  points_ = gl::Texture(GL_TEXTURE_2D_ARRAY);
  depths_ = gl::Texture(GL_TEXTURE_2D_ARRAY);
  layers_ = layers;
  glTextureStorage3D(points_.name(), 1, GL_RG16F, size_, size_, layers);
  glTextureStorage3D(depths_.name(), 1, GL_DEPTH_COMPONENT32F, size_, size_, layers);
}

void SilhouettePass::render(const GpuScene& scene, const GpuScene::PlantDraws* plants, const shadow::ShadowSetup& setup,
                            int layer, const shadow::Light& light) {
  if (static_cast<int>(setup.views.size()) > layers_) allocate(static_cast<int>(setup.views.size()));
  const GLuint fb = framebuffer_.name();
  gl::draw_depth_tested(framebuffer_, size_, size_);
  glNamedFramebufferTextureLayer(fb, GL_COLOR_ATTACHMENT0, points_.name(), 0, layer);
  glNamedFramebufferTextureLayer(fb, GL_DEPTH_ATTACHMENT, depths_.name(), 0, layer);
  const float no_edge[4] = {-1.0f, -1.0f, 0.0f, 0.0f};
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(fb, GL_COLOR, 0, no_edge);
  glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
  const shadow::ShadowView& view = setup.views[static_cast<std::size_t>(layer)];
  if (view.paraboloid) return;
  edges_.draw(scene, plants, [&](const gl::Program& program) {
    gl::set_uniform(program, "map_size", static_cast<float>(size_));
    gl::set_uniform(program, "light", shadow::homogeneous(light));
    gl::set_uniform(program, "light_view_projection", view.view_projection());
  }, view.view_projection());
}

}  // namespace ecoview
