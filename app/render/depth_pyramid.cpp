#include "app/render/depth_pyramid.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"
#include "app/render/buffer_texture_units.hpp"

#include <algorithm>
#include <string>

namespace ecoview {
namespace {

constexpr GLuint pyramid_binding = 17, point_depths_binding = 6;  // shaders/depth_pyramid.glsl, point_common.glsl
constexpr int max_levels = 16;                                     // the shaders' arrays
constexpr int tile = 8;                                            // local size per side
constexpr int base_levels = 3, base_block = 4;                     // levels 0-2, 4 × 4 pixels a thread
constexpr GLuint frame_depths_binding = 25;                        // shaders/receiver_marks.comp
constexpr GLuint whole_binding = 29, commands_binding = 30;  // shaders/pyramid_dispatch.comp
constexpr GLuint changed_tiles_binding = 39, changed_list_binding = 40;  // shaders/depth_pyramid.glsl
constexpr int tile_pixels = base_block * tile;                           // a base work group's, per side
// The frame's pixels that mark receivers: every 2nd each way, far denser than the marks' texels.
constexpr int receiver_pixel_step = 2;

GLuint groups(int texels) { return static_cast<GLuint>((texels + tile - 1) / tile); }

}  // namespace

DepthPyramid::DepthPyramid(glm::ivec2 size)
    : size_(size),
      base_program_(gl::build_program({"depth_pyramid.comp"}, "#define BASE\n")),
      reduce_program_(gl::build_program({"depth_pyramid.comp"})),
      list_program_(gl::build_program({"pyramid_dispatch.comp"}, "#define LIST\n")),
      dispatch_program_(gl::build_program({"pyramid_dispatch.comp"})),
      clear_marks_program_(gl::build_program({"receiver_marks.comp"}, "#define CLEAR\n")),
      marks_program_(gl::build_program({"receiver_marks.comp"})) {
  GLuint total = 0;
  for (glm::ivec2 s = size; static_cast<int>(sizes_.size()) < max_levels; s = (s + 1) / 2) {
    sizes_.push_back(s);
    offsets_.push_back(total);
    total += static_cast<GLuint>(s.x * s.y);
    if (s.x == 1 && s.y == 1) break;
  }
  glNamedBufferStorage(depths_.name(), static_cast<GLsizeiptr>(total * sizeof(float)), nullptr, 0);
  depth_texels_ = gl::buffer_texels(depths_, GL_R32F);
  const glm::ivec2 tiles = tile_counts();
  const auto tile_count = static_cast<std::size_t>(tiles.x) * static_cast<std::size_t>(tiles.y);
  gl::store(changed_tiles_, std::vector<GLuint>(tile_count, 0u));
  glNamedBufferStorage(changed_list_.name(), static_cast<GLsizeiptr>(tile_count * sizeof(GLuint)), nullptr, 0);
  std::vector<glm::uvec4> whole{{static_cast<GLuint>(tile_count), 1, 1, 0}};
  for (std::size_t level = 1; level < sizes_.size(); ++level) whole.emplace_back(groups(sizes_[level].x), groups(sizes_[level].y), 1, 0);
  gl::store(whole_, whole);
  gl::store(commands_, std::vector<glm::uvec4>(whole.size() + 1, glm::uvec4(0)));
}

void DepthPyramid::dispatch(const gl::Buffer& passes, std::size_t pass) const {
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, passes.name());
  glDispatchComputeIndirect(static_cast<GLintptr>(pass * sizeof(glm::uvec4)));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

void DepthPyramid::set_levels(const gl::Program& program) const {
  const GLuint p = program.name();
  glProgramUniform1uiv(p, glGetUniformLocation(p, "pyramid_offset"), static_cast<GLsizei>(offsets_.size()), offsets_.data());
  glProgramUniform2iv(p, glGetUniformLocation(p, "pyramid_size"), static_cast<GLsizei>(sizes_.size()), &sizes_.front().x);
  gl::set_uniform(program, "pyramid_levels", static_cast<int>(sizes_.size()));
}

// The tiles all listed on the GPU, not marked by a buffer clear: on llvmpipe a clear could land
// after the pass behind it.
void DepthPyramid::build(GLuint polygon_depth, GLuint point_depths) const { build_tiles(true, polygon_depth, point_depths); }

void DepthPyramid::build_changed(GLuint polygon_depth, GLuint point_depths) const { build_tiles(false, polygon_depth, point_depths); }

// Past a band that drew little, little of the pyramid changes: on llvmpipe a whole build of a
// 960 × 540 one takes about 6 ms, 13 times a frame on the ecosystem's default view.
void DepthPyramid::build_tiles(bool whole_image, GLuint polygon_depth, GLuint point_depths) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, changed_tiles_binding, changed_tiles_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, changed_list_binding, changed_list_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, whole_binding, whole_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, commands_binding, commands_.name());
  const glm::ivec2 tiles = tile_counts();
  set_levels(list_program_);
  gl::set_uniform(list_program_, "pass_count", static_cast<unsigned>(sizes_.size()));
  gl::set_uniform(list_program_, "whole_image", whole_image ? 1 : 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glUseProgram(list_program_.name());
  glDispatchCompute(static_cast<GLuint>((tiles.x * tiles.y + 63) / 64), 1, 1);
  gl::set_uniform(dispatch_program_, "pass_count", static_cast<unsigned>(sizes_.size()));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(dispatch_program_.name());
  glDispatchCompute(1, 1, 1);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, pyramid_binding, depths_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, point_depths_binding, point_depths);
  glBindTextureUnit(0, polygon_depth);
  set_levels(base_program_);
  gl::set_uniform(base_program_, "polygon_depth", 0);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glUseProgram(base_program_.name());
  dispatch(commands_, 0);
  reduce(commands_, base_levels);
}

void DepthPyramid::build_receivers(const DepthPyramid& frame, const glm::mat4& frame_view_projection,
                                   const glm::mat4& map_view_projection, const std::vector<glm::mat4>& earlier, float map_texels) const {
  if (earlier.size() > 8) throw RuntimeFailure("a receiver mask leaves out at most 8 earlier cascades");
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, pyramid_binding, depths_.name());
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, frame_depths_binding, frame.depths_.name(), 0,
                    static_cast<GLsizeiptr>(frame.size_.x) * frame.size_.y * static_cast<GLsizeiptr>(sizeof(float)));
  fill_marks(0.0f);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  set_levels(marks_program_);
  gl::set_uniform(marks_program_, "frame_size", frame.size_);
  gl::set_uniform(marks_program_, "pixel_step", receiver_pixel_step);
  gl::set_uniform(marks_program_, "frame_to_world", glm::inverse(frame_view_projection));
  gl::set_uniform(marks_program_, "map_view_projection", map_view_projection);
  gl::set_uniform(marks_program_, "earlier_count", static_cast<int>(earlier.size()));
  gl::set_uniform(marks_program_, "map_texels", map_texels);
  if (!earlier.empty()) {
    const GLuint p = marks_program_.name();
    glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "earlier_views"), static_cast<GLsizei>(earlier.size()), GL_FALSE, &earlier.front()[0][0]);
  }
  glUseProgram(marks_program_.name());
  glDispatchCompute(groups((frame.size_.x + receiver_pixel_step - 1) / receiver_pixel_step),
                    groups((frame.size_.y + receiver_pixel_step - 1) / receiver_pixel_step), 1);
  reduce(whole_, 1);
}

void DepthPyramid::mark_everywhere() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, pyramid_binding, depths_.name());
  fill_marks(1.0f);
  reduce(whole_, 1);
}

void DepthPyramid::fill_marks(float mark) const {
  set_levels(clear_marks_program_);
  gl::set_uniform(clear_marks_program_, "mark", mark);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(clear_marks_program_.name());
  glDispatchCompute(groups(size_.x), groups(size_.y), 1);
}

void DepthPyramid::reduce(const gl::Buffer& passes, std::size_t first_level) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, pyramid_binding, depths_.name());
  set_levels(reduce_program_);
  glUseProgram(reduce_program_.name());
  for (std::size_t level = first_level; level < sizes_.size(); ++level) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gl::set_uniform(reduce_program_, "level", static_cast<int>(level));
    dispatch(passes, level);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);  // its readers fetch texels
}

void DepthPyramid::bind_for(const gl::Program& program) const {
  glBindTextureUnit(pyramid_texels_unit, depth_texels_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, changed_tiles_binding, changed_tiles_.name());
  set_levels(program);
}

std::vector<float> DepthPyramid::read(std::size_t level) const {
  std::vector<float> texels(static_cast<std::size_t>(sizes_[level].x) * static_cast<std::size_t>(sizes_[level].y));
  glGetNamedBufferSubData(depths_.name(), static_cast<GLintptr>(offsets_[level] * sizeof(float)),
                          static_cast<GLsizeiptr>(texels.size() * sizeof(float)), texels.data());
  return texels;
}

glm::ivec2 DepthPyramid::tile_counts() const { return (size_ + tile_pixels - 1) / tile_pixels; }

std::vector<bool> DepthPyramid::read_changed_tiles() const {
  const glm::ivec2 tiles = tile_counts();
  std::vector<GLuint> flags(static_cast<std::size_t>(tiles.x) * static_cast<std::size_t>(tiles.y));
  glGetNamedBufferSubData(changed_tiles_.name(), 0, static_cast<GLsizeiptr>(flags.size() * sizeof(GLuint)), flags.data());
  std::vector<bool> changed;
  for (GLuint f : flags) changed.push_back(f != 0u);
  return changed;
}

}  // namespace ecoview
