#include "app/render/shadow_pass.hpp"

#include "app/gl/shader_program.hpp"

namespace ecoview {
namespace {

const std::vector<std::string> paraboloid_stages{"world_position.vert", "shadow_paraboloid.tesc", "shadow_paraboloid.tese", "shadow_depth.frag"};
const std::string plant_index = "#define PLANT_INDEX\n";

GLenum internal_format(ShadowDepth depth) {
  switch (depth) {
    case ShadowDepth::fixed16: return GL_DEPTH_COMPONENT16;
    case ShadowDepth::fixed24: return GL_DEPTH_COMPONENT24;
    case ShadowDepth::float32: return GL_DEPTH_COMPONENT32F;
  }
  return GL_DEPTH_COMPONENT32F;
}

}  // namespace

void make_comparable(GLuint t) {
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(t, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  // Outside the map nothing was rendered: depth 1 there reads as lit.
  glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTextureParameterfv(t, GL_TEXTURE_BORDER_COLOR, border);
}

ShadowPass::ShadowPass(int size, DepthBias bias, ShadowDepth depth, bool surface_textures)
    : size_(size),
      bias_(bias),
      format_(internal_format(depth)),
      program_(gl::build_program({"shadow_depth.vert", "shadow_depth.frag"}, gl::surface_defines(surface_textures))),
      plant_program_(gl::build_program({"shadow_depth.vert", "shadow_depth.frag"}, gl::surface_defines(surface_textures) + plant_index)),
      paraboloid_program_(gl::build_program(paraboloid_stages, gl::surface_defines(surface_textures))),
      plant_paraboloid_program_(gl::build_program(paraboloid_stages, gl::surface_defines(surface_textures) + plant_index)) {
  allocate(1);
}

// Texture storage is immutable: a setup with more views than allocated gets a new texture.
void ShadowPass::allocate(int layers) {
  depth_ = gl::Texture(GL_TEXTURE_2D_ARRAY);
  layers_ = layers;
  const GLuint t = depth_.name();
  glTextureStorage3D(t, 1, format_, size_, size_, layers);
  make_comparable(t);
  glNamedFramebufferDrawBuffer(framebuffer_.name(), GL_NONE);
  glNamedFramebufferReadBuffer(framebuffer_.name(), GL_NONE);
}

void ShadowPass::reserve_layers(int layers) {
  if (layers > layers_) allocate(layers);
}

void ShadowPass::clear_layer(int layer) {
  const GLuint fb = framebuffer_.name();
  glNamedFramebufferTextureLayer(fb, GL_DEPTH_ATTACHMENT, depth_.name(), 0, layer);
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
}

void ShadowPass::render(const GpuScene& scene, const shadow::ShadowSetup& setup, int layer, const GpuScene::PlantDraws* plants) {
  reserve_layers(static_cast<int>(setup.views.size()));
  gl::draw_depth_tested(framebuffer_, size_, size_);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(bias_.slope, bias_.constant);
  clear_layer(layer);
  const shadow::ShadowView& view = setup.views[static_cast<std::size_t>(layer)];
  const gl::Program& scene_program = view.paraboloid ? paraboloid_program_ : program_;
  const gl::Program& plant_program = view.paraboloid ? plant_paraboloid_program_ : plant_program_;
  for (const gl::Program* p : {&scene_program, &plant_program}) {
    if (view.paraboloid) {
      gl::set_uniform(*p, "light_view", view.view);
      gl::set_uniform(*p, "paraboloid", view.paraboloid_parameters());
    } else {
      gl::set_uniform(*p, "light_view_projection", view.view_projection());
    }
  }
  const GLenum mode = view.paraboloid ? GL_PATCHES : GL_TRIANGLES;
  if (view.paraboloid) {
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    glEnable(GL_CLIP_DISTANCE0);
  }
  glUseProgram(scene_program.name());
  scene.draw(mode, view.clip_matrix());
  if (plants) {
    glUseProgram(plant_program.name());
    scene.draw_chosen(*plants, mode);
  }
  glDisable(GL_CLIP_DISTANCE0);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

Image<float> ShadowPass::read_layer(int layer) const {
  std::vector<float> bottom_up(static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_));
  glGetTextureSubImage(depth_.name(), 0, 0, 0, layer, size_, size_, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                       static_cast<GLsizei>(bottom_up.size() * sizeof(float)), bottom_up.data());
  return from_bottom_up(size_, size_, 1, bottom_up);
}

}  // namespace ecoview
