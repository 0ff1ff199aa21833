#include "app/render/frame_pass.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

namespace ecoview {
namespace {

const glm::vec3 sky_color(0.62f, 0.74f, 0.86f);  // sRGB
constexpr GLuint nearest_binding = 26;  // shaders/nearest_depth.comp

// Attaches `targets` as colour attachments 0, 1, ... and draws into all of them.
void attach(const gl::Framebuffer& framebuffer, std::initializer_list<const gl::Texture*> targets) {
  std::vector<GLenum> buffers;
  for (const gl::Texture* target : targets) {
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(buffers.size());
    glNamedFramebufferTexture(framebuffer.name(), attachment, target->name(), 0);
    buffers.push_back(attachment);
  }
  glNamedFramebufferDrawBuffers(framebuffer.name(), static_cast<GLsizei>(buffers.size()), buffers.data());
  if (glCheckNamedFramebufferStatus(framebuffer.name(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw RuntimeFailure("the frame's render targets are not supported by this driver; try another --backend");
  }
}

}  // namespace

FramePass::FramePass(int width, int height, bool aliasing)
    : width_(width),
      height_(height),
      aliasing_wanted_(aliasing),
      surface_program_(gl::build_program({"frame.vert", "surface.frag"})),
      point_program_(gl::build_program({"fullscreen.vert", "point_surface.frag"})),
      nearest_program_(gl::build_program({"nearest_depth.comp"})) {
  glNamedBufferStorage(nearest_.name(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glTextureStorage2D(normals_.name(), 1, GL_RGBA32F, width, height);
  glTextureStorage2D(albedos_.name(), 1, GL_RGBA32F, width, height);
  glTextureStorage2D(depth_.name(), 1, GL_R32F, width, height);
  glTextureStorage2D(depth_buffer_.name(), 1, GL_DEPTH32F_STENCIL8, width, height);
  glNamedFramebufferTexture(surfaces_.name(), GL_DEPTH_STENCIL_ATTACHMENT, depth_buffer_.name(), 0);
  attach(surfaces_, {&normals_, &albedos_, &depth_});

  glTextureStorage2D(color_.name(), 1, GL_RGBA8, width, height);
  glTextureStorage2D(visibility_.name(), 1, GL_R8, width, height);
  glTextureStorage2D(aliasing_.name(), 1, GL_R32F, width, height);
  attach(lit_, {&color_, &visibility_, &aliasing_});
}

void FramePass::set_camera(const gl::Program& program, const shadow::Camera& camera) const {
  const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
  gl::set_uniform(program, "view", camera.view());
  gl::set_uniform(program, "view_projection", camera.projection(aspect) * camera.view());
  gl::set_uniform(program, "camera_position", camera.position);
}

void FramePass::draw_surfaces(const GpuScene& scene, const shadow::Camera& camera) const {
  const GLuint fb = surfaces_.name();
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glViewport(0, 0, width_, height_);
  const float no_surface[4] = {-1.0f, 0.0f, 0.0f, 0.0f};
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(fb, GL_COLOR, 2, no_surface);
  glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
  start_surfaces(camera);
  scene.draw();
}

void FramePass::add_chosen_surfaces(const GpuScene& scene, const GpuSampler& sampler, int band, const shadow::Camera& camera) const {
  start_surfaces(camera);
  scene.draw_chosen(sampler, band, band + 1);
}

void FramePass::start_surfaces(const shadow::Camera& camera) const {
  glBindFramebuffer(GL_FRAMEBUFFER, surfaces_.name());
  glViewport(0, 0, width_, height_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glUseProgram(surface_program_.name());
  set_camera(surface_program_, camera);
}

void FramePass::add_points(const PointSplat& points, const shadow::Camera& camera) const {
  glBindFramebuffer(GL_FRAMEBUFFER, surfaces_.name());
  glViewport(0, 0, width_, height_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(point_program_.name());
  set_camera(point_program_, camera);
  points.bind_for(point_program_);
  draw_fullscreen();
}

FramePass::ShadeVariant FramePass::shade_variant(const std::optional<ShadowLookup>& shadow_map) const {
  ShadeVariant variant;
  variant.aliasing = aliasing_wanted_;
  if (!shadow_map) return variant;
  variant.shadows = true;
  variant.selection = static_cast<int>(shadow_map->setup.selection);
  for (const shadow::ShadowView& view : shadow_map->setup.views) variant.paraboloid |= view.paraboloid.has_value();
  return variant;
}

const gl::Program& FramePass::shade_program(const ShadeVariant& variant) const {
  auto found = shade_programs_.find(variant);
  if (found != shade_programs_.end()) return found->second;
  const auto boolean = [](bool b) { return b ? std::string("true") : std::string("false"); };
  const std::string defines = "#define SHADOWS " + boolean(variant.shadows) + "\n#define SHADOW_SELECTION " +
                              std::to_string(variant.selection) + "\n#define PARABOLOID_VIEWS " +
                              boolean(variant.paraboloid) + "\n#define ALIASING " + boolean(variant.aliasing) + "\n";
  return shade_programs_.emplace(variant, gl::build_program({"fullscreen.vert", "shade.frag"}, defines)).first->second;
}

void FramePass::set_light(const gl::Program& program, const shadow::Light& light,
                          const std::optional<ShadowLookup>& shadow_map) const {
  gl::set_uniform(program, "frame_size", glm::vec2(width_, height_));
  gl::set_uniform(program, "light_type", static_cast<int>(light.type));
  gl::set_uniform(program, "light_position", light.position);
  gl::set_uniform(program, "light_direction", glm::normalize(light.direction));
  gl::set_uniform(program, "spot_cos_cone", std::cos(glm::radians(light.cone_deg)));
  if (shadow_map) {
    const shadow::ShadowSetup& setup = shadow_map->setup;
    gl::set_uniform(program, "shadow_view_count", static_cast<int>(setup.views.size()));
    for (std::size_t i = 0; i < setup.views.size(); ++i) {
      const shadow::ShadowView& view = setup.views[i];
      const std::string index = std::string("[").append(std::to_string(i)).append("]");
      gl::set_uniform(program, ("shadow_matrices" + index).c_str(), view.view_projection());
      gl::set_uniform(program, ("shadow_paraboloids" + index).c_str(), view.paraboloid_parameters());
    }
    gl::set_uniform(program, "shadow_size", static_cast<float>(shadow_map->size));
    glBindTextureUnit(setup.selection == shadow::ViewSelection::screen_mask ? 1 : 0, shadow_map->texture);
  }
}

void FramePass::shade(const shadow::Camera& camera, const shadow::Light& light,
                      const std::optional<ShadowLookup>& shadow_map) const {
  const GLuint fb = lit_.name();
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glViewport(0, 0, width_, height_);
  const float sky[4] = {sky_color.r, sky_color.g, sky_color.b, 1.0f};
  const float fully_visible[4] = {1.0f, 0.0f, 0.0f, 0.0f};
  const float no_surface[4] = {-1.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(fb, GL_COLOR, 0, sky);
  glClearNamedFramebufferfv(fb, GL_COLOR, 1, fully_visible);
  glClearNamedFramebufferfv(fb, GL_COLOR, 2, no_surface);
  glDisable(GL_DEPTH_TEST);

  const gl::Program& program = shade_program(shade_variant(shadow_map));
  glUseProgram(program.name());
  set_camera(program, camera);
  const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
  gl::set_uniform(program, "camera_forward", camera.forward());
  gl::set_uniform(program, "pixel_to_world", glm::inverse(camera.projection(aspect) * camera.view()));
  set_light(program, light, shadow_map);
  glBindTextureUnit(2, normals_.name());
  glBindTextureUnit(3, albedos_.name());
  glBindTextureUnit(4, depth_.name());
  draw_fullscreen();
  glEnable(GL_DEPTH_TEST);
}

void FramePass::draw_fullscreen() const {
  glBindVertexArray(empty_vertex_array_.name());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

template <class Sample>
Image<Sample> FramePass::read(const gl::Framebuffer& framebuffer, GLenum attachment, int channels, GLenum format,
                              GLenum type) const {
  std::vector<Sample> bottom_up(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * static_cast<std::size_t>(channels));
  glNamedFramebufferReadBuffer(framebuffer.name(), attachment);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.name());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, format, type, bottom_up.data());
  return from_bottom_up(width_, height_, channels, bottom_up);
}

Image8 FramePass::read_color() const { return read<std::uint8_t>(lit_, GL_COLOR_ATTACHMENT0, 3, GL_RGB, GL_UNSIGNED_BYTE); }
Image8 FramePass::read_visibility() const { return read<std::uint8_t>(lit_, GL_COLOR_ATTACHMENT1, 1, GL_RED, GL_UNSIGNED_BYTE); }
Image<float> FramePass::read_depth() const { return read<float>(surfaces_, GL_COLOR_ATTACHMENT2, 1, GL_RED, GL_FLOAT); }

// Set by an upload, not a buffer clear: on llvmpipe a clear could land after the pass behind it.
float FramePass::nearest_depth() const {
  const GLuint none = 0xFFFFFFFFu;
  glNamedBufferSubData(nearest_.name(), 0, sizeof none, &none);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, nearest_binding, nearest_.name());
  glBindTextureUnit(0, depth_.name());
  gl::set_uniform(nearest_program_, "view_depth", 0);
  glUseProgram(nearest_program_.name());
  glDispatchCompute(static_cast<GLuint>((width_ + 15) / 16), static_cast<GLuint>((height_ + 15) / 16), 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint bits = none;
  glGetNamedBufferSubData(nearest_.name(), 0, sizeof bits, &bits);
  float depth = 0.0f;
  if (bits != none) std::memcpy(&depth, &bits, sizeof depth);
  return depth;
}
Image<float> FramePass::read_aliasing() const { return read<float>(lit_, GL_COLOR_ATTACHMENT2, 1, GL_RED, GL_FLOAT); }

void FramePass::present(int width, int height) const {
  glNamedFramebufferReadBuffer(lit_.name(), GL_COLOR_ATTACHMENT0);
  glBlitNamedFramebuffer(lit_.name(), 0, 0, 0, width_, height_, 0, 0, width, height,
                         GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

}  // namespace ecoview
