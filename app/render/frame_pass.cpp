#include "app/render/frame_pass.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"
#include "app/render/buffer_texture_units.hpp"
#include "app/scene/scene_fields.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

namespace ecoview {
namespace {

const glm::vec3 sky_color(0.62f, 0.74f, 0.86f);  // sRGB
constexpr GLuint nearest_binding = 26;  // shaders/shade.comp
// shaders/predicted_aliasing.comp: histograms of log2 of the aliasing factor, from 2^-10 (the
// first bin taking all below) to 2^14 (the last taking all above: where the light grazes), fine
// enough that methods a quarter of a percent apart get different bins; up to this many setups at once.
constexpr GLuint histograms_binding = 27;
constexpr int bins_per_octave = 256, lowest_octave = -10, histogram_bins = 24 * bins_per_octave, most_predicted_setups = 8;
// predict_aliasing reads about this many of the frame's pixels, whatever its size: the median of n
// samples stands within about sqrt(0.25 / n) of its rank (0.5 points of percentile at 10,000).
constexpr float predicting_pixels = 10000.0f;

// The value `fraction` of the way up the counts of a histogram, in rank (shadow::percentile's
// rank), as its bin's centre; 0 for none.
float percentile_of(const GLuint* bins, float fraction) {
  std::uint64_t total = 0;
  for (int b = 0; b < histogram_bins; ++b) total += bins[b];
  if (total == 0) return 0.0f;
  const auto rank = static_cast<std::uint64_t>(static_cast<double>(fraction) * static_cast<double>(total - 1));
  std::uint64_t below = 0;
  int b = 0;
  while (below + bins[b] <= rank) below += bins[b++];
  return std::exp2((static_cast<float>(b) + 0.5f) / static_cast<float>(bins_per_octave) + static_cast<float>(lowest_octave));
}

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

FramePass::FramePass(int width, int height, bool aliasing, bool surface_textures)
    : width_(width),
      height_(height),
      aliasing_wanted_(aliasing),
      surface_program_(gl::build_program({"frame.vert", "surface.frag"}, gl::surface_defines(surface_textures))),
      plant_surface_program_(gl::build_program({"frame.vert", "surface.frag"}, gl::surface_defines(surface_textures) + "#define PLANT_INDEX\n")),
      point_program_(gl::build_program({"fullscreen.vert", "point_surface.frag"})) {
  glNamedBufferStorage(nearest_.name(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(histograms_.name(), most_predicted_setups * histogram_bins * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
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

glm::mat4 FramePass::view_projection(const shadow::Camera& camera) const {
  return camera.projection(static_cast<float>(width_) / static_cast<float>(height_)) * camera.view();
}

void FramePass::set_camera(const gl::Program& program, const shadow::Camera& camera) const {
  gl::set_uniform(program, "view", camera.view());
  gl::set_uniform(program, "view_projection", view_projection(camera));
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
  points_added_ = false;
  start_surfaces(surface_program_, camera);
  scene.draw(GL_TRIANGLES, view_projection(camera));
}

void FramePass::add_chosen_surfaces(const GpuScene& scene, const GpuSampler& sampler, int band, const shadow::Camera& camera) const {
  start_surfaces(plant_surface_program_, camera);
  scene.draw_chosen(sampler.frame_polygon_draws(band));
}

void FramePass::start_surfaces(const gl::Program& program, const shadow::Camera& camera) const {
  gl::draw_depth_tested(surfaces_, width_, height_);
  glUseProgram(program.name());
  set_camera(program, camera);
}

void FramePass::add_points(const PointSplat& points, const shadow::Camera& camera) const {
  if (!point_surfaces_) {
    point_surfaces_ = std::make_unique<Surfaces>();
    glTextureStorage2D(point_surfaces_->normals.name(), 1, GL_RGBA32F, width_, height_);
    glTextureStorage2D(point_surfaces_->albedos.name(), 1, GL_RGBA32F, width_, height_);
    glTextureStorage2D(point_surfaces_->depth.name(), 1, GL_R32F, width_, height_);
    glNamedFramebufferTexture(point_surfaces_->framebuffer.name(), GL_DEPTH_STENCIL_ATTACHMENT, depth_buffer_.name(), 0);
    attach(point_surfaces_->framebuffer, {&point_surfaces_->normals, &point_surfaces_->albedos, &point_surfaces_->depth});
  }
  const float no_surface[4] = {-1.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(point_surfaces_->framebuffer.name(), GL_COLOR, 2, no_surface);
  points_added_ = true;
  glBindFramebuffer(GL_FRAMEBUFFER, point_surfaces_->framebuffer.name());
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
  variant.marks_edges = shadow_map->marks_edges;
  variant.point_layers = shadow_map->point_layers;
  variant.silhouettes = shadow_map->silhouettes != 0;
  variant.pages = shadow_map->page_table != 0;
  for (const shadow::ShadowView& view : shadow_map->setup.views) variant.paraboloid |= view.paraboloid.has_value();
  return variant;
}

std::string FramePass::defines(const ShadeVariant& variant) {
  const auto boolean = [](bool b) { return b ? std::string("true") : std::string("false"); };
  return "#define SHADOWS " + boolean(variant.shadows) + "\n#define SHADOW_SELECTION " + std::to_string(variant.selection) +
         "\n#define PARABOLOID_VIEWS " + boolean(variant.paraboloid) + "\n#define ALIASING " + boolean(variant.aliasing) +
         "\n#define MARK_EDGES " + boolean(variant.marks_edges) + "\n#define POINT_LAYERS " + boolean(variant.point_layers) +
         "\n#define SILHOUETTES " + boolean(variant.silhouettes) + "\n#define VIRTUAL_PAGES " + boolean(variant.pages) + "\n";
}

const gl::Program& FramePass::shade_program(const ShadeVariant& variant) const {
  auto found = shade_programs_.find(variant);
  if (found != shade_programs_.end()) return found->second;
  return shade_programs_.emplace(variant, gl::build_program({"shade.comp"}, defines(variant))).first->second;
}

const gl::Program& FramePass::prediction_program(const ShadeVariant& variant) const {
  auto found = prediction_programs_.find(variant);
  if (found != prediction_programs_.end()) return found->second;
  return prediction_programs_.emplace(variant, gl::build_program({"predicted_aliasing.comp"}, defines(variant))).first->second;
}

void FramePass::set_lighting(const gl::Program& program, const shadow::Camera& surface_camera, const shadow::Camera& camera,
                             const shadow::Light& light, const std::optional<ShadowLookup>& shadow_map) const {
  const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
  set_camera(program, surface_camera);
  gl::set_uniform(program, "view_projection", camera.projection(aspect) * camera.view());
  set_surface_camera(program, surface_camera);
  set_light(program, light, shadow_map);
}

std::vector<float> FramePass::predict_aliasing(const shadow::Camera& surface_camera, const shadow::Camera& camera,
                                               const shadow::Light& light, const std::vector<shadow::ShadowSetup>& setups,
                                               int map_size, float fraction) const {
  if (setups.size() > static_cast<std::size_t>(most_predicted_setups)) throw RuntimeFailure("predict_aliasing takes at most 8 setups");
  // Zeros uploaded, not cleared: on llvmpipe a clear could land after the pass behind it.
  std::vector<GLuint> bins(setups.size() * histogram_bins, 0u);
  if (bins.empty()) return {};
  glNamedBufferSubData(histograms_.name(), 0, static_cast<GLsizeiptr>(bins.size() * sizeof(GLuint)), bins.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, histograms_binding, histograms_.name());
  const int step = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<float>(width_ * height_) / predicting_pixels))));
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  for (std::size_t i = 0; i < setups.size(); ++i) {
    const ShadowLookup lookup{0, setups[i], map_size};
    ShadeVariant variant = shade_variant(lookup);
    variant.aliasing = true;
    const gl::Program& program = prediction_program(variant);
    glUseProgram(program.name());
    set_lighting(program, surface_camera, camera, light, lookup);
    bind_surfaces(program);
    gl::set_uniform(program, "pixel_step", step);
    gl::set_uniform(program, "first_bin", static_cast<unsigned>(i * histogram_bins));
    gl::set_uniform(program, "bin_count", static_cast<unsigned>(histogram_bins));
    gl::set_uniform(program, "bins_per_octave", static_cast<float>(bins_per_octave));
    gl::set_uniform(program, "lowest_octave", static_cast<float>(lowest_octave));
    glDispatchCompute(static_cast<GLuint>((width_ / step + 8) / 8), static_cast<GLuint>((height_ / step + 8) / 8), 1);
  }
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(histograms_.name(), 0, static_cast<GLsizeiptr>(bins.size() * sizeof(GLuint)), bins.data());
  std::vector<float> predicted;
  for (std::size_t i = 0; i < setups.size(); ++i) predicted.push_back(percentile_of(&bins[i * histogram_bins], fraction));
  return predicted;
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
    if (shadow_map->silhouettes != 0) glBindTextureUnit(silhouette_points_unit, shadow_map->silhouettes);
    if (shadow_map->silhouette_depths != 0) glBindTextureUnit(silhouette_depths_unit, shadow_map->silhouette_depths);
    if (shadow_map->page_table != 0) {
      const shadow::VirtualMap& pages = shadow_map->pages;
      gl::set_uniform(program, "page_levels", pages.levels);
      gl::set_uniform(program, "page_texels", static_cast<float>(pages.page_texels));
      gl::set_uniform(program, "page_guard", static_cast<float>(pages.guard));
      gl::set_uniform(program, "page_pixel_texels", static_cast<float>(pages.pixel_texels));
      gl::set_uniform(program, "page_window", pages.window);
      const std::vector<glm::ivec2>& windows = shadow_map->page_windows;
      if (!windows.empty()) {
        glProgramUniform2iv(program.name(), glGetUniformLocation(program.name(), "page_window_origins"),
                            static_cast<GLsizei>(windows.size()), glm::value_ptr(windows.front()));
      }
      glBindTextureUnit(page_table_unit, shadow_map->page_table);
    }
  }
}

void FramePass::request_pages(const shadow::Camera& camera, const shadow::Light& light, const ShadowLookup& pages) const {
  const ShadeVariant variant = shade_variant(pages);
  auto found = request_programs_.find(variant);
  if (found == request_programs_.end()) {
    found = request_programs_.emplace(variant, gl::build_program({"page_requests.comp"}, defines(variant))).first;
  }
  const gl::Program& program = found->second;
  glUseProgram(program.name());
  set_lighting(program, camera, camera, light, pages);
  bind_surfaces(program);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((width_ + 7) / 8), static_cast<GLuint>((height_ + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void FramePass::shade(const shadow::Camera& camera, const shadow::Light& light,
                      const std::optional<ShadowLookup>& shadow_map) const {
  const gl::Program& program = shade_program(shade_variant(shadow_map));
  glUseProgram(program.name());
  set_lighting(program, camera, camera, light, shadow_map);
  bind_surfaces(program);
  gl::set_uniform(program, "sky", srgb_to_linear(sky_color));
  // Set by an upload, not a buffer clear: on llvmpipe a clear could land after the pass behind it.
  const GLuint none = 0xFFFFFFFFu;
  glNamedBufferSubData(nearest_.name(), 0, sizeof none, &none);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, nearest_binding, nearest_.name());
  glBindImageTexture(0, color_.name(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glBindImageTexture(1, visibility_.name(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
  glBindImageTexture(2, aliasing_.name(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((width_ + 7) / 8), static_cast<GLuint>((height_ + 7) / 8), 1);
  // Read back, blitted to a window, or sampled by the next frame's passes.
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
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
void FramePass::bind_surfaces(const gl::Program& program) const {
  glBindTextureUnit(2, normals_.name());
  glBindTextureUnit(3, albedos_.name());
  glBindTextureUnit(4, depth_.name());
  if (point_surfaces_) {
    glBindTextureUnit(5, point_surfaces_->normals.name());
    glBindTextureUnit(6, point_surfaces_->albedos.name());
    glBindTextureUnit(7, point_surfaces_->depth.name());
  }
  gl::set_uniform(program, "points_added", points_added_ ? 1 : 0);
}

void FramePass::set_surface_camera(const gl::Program& program, const shadow::Camera& surface_camera) const {
  gl::set_uniform(program, "camera_forward", surface_camera.forward());
  gl::set_uniform(program, "pixel_to_world", glm::inverse(view_projection(surface_camera)));
}

void FramePass::bind_surfaces_for(const gl::Program& program, const shadow::Camera& camera) const {
  gl::set_uniform(program, "camera_position", camera.position);
  gl::set_uniform(program, "frame_size", glm::vec2(width_, height_));
  set_surface_camera(program, camera);
  bind_surfaces(program);
}

// The point's depth where the point pass added one, else the polygons'.
Image<float> FramePass::read_depth() const {
  Image<float> depth = read<float>(surfaces_, GL_COLOR_ATTACHMENT2, 1, GL_RED, GL_FLOAT);
  if (!points_added_) return depth;
  const Image<float> points = read<float>(point_surfaces_->framebuffer, GL_COLOR_ATTACHMENT2, 1, GL_RED, GL_FLOAT);
  for (std::size_t i = 0; i < depth.samples.size(); ++i) {
    if (points.samples[i] >= 0.0f) depth.samples[i] = points.samples[i];
  }
  return depth;
}

float FramePass::nearest_depth() const {
  const GLuint none = 0xFFFFFFFFu;
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
