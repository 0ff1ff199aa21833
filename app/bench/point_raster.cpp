#include "app/bench/point_raster.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"
#include "app/render/buffer_texture_units.hpp"
#include "app/render/plant_pose.hpp"

#include <numeric>

namespace ecoview {
namespace {


// glMultiDrawArraysIndirect's command layout.
struct DrawCommand {
  GLuint count, instance_count, first, base_instance;
};

constexpr GLuint draws_binding = 0;  // point_raster.vert

}  // namespace

PointRaster::PointRaster(glm::ivec2 size) : size_(size), program_(gl::build_program({"point_raster.vert", "point_raster.frag"})) {
  glTextureStorage2D(color_.name(), 1, GL_RGBA8, size.x, size.y);
  glTextureStorage2D(depth_.name(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
  glNamedFramebufferTexture(framebuffer_.name(), GL_COLOR_ATTACHMENT0, color_.name(), 0);
  glNamedFramebufferTexture(framebuffer_.name(), GL_DEPTH_ATTACHMENT, depth_.name(), 0);
  if (glCheckNamedFramebufferStatus(framebuffer_.name(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw RuntimeFailure("the point raster's render targets are not supported by this driver");
  }
  // Attribute 0: the instance of an indirect command, one per instance from its baseInstance.
  glEnableVertexArrayAttrib(vertex_array_.name(), 0);
  glVertexArrayAttribIFormat(vertex_array_.name(), 0, 1, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(vertex_array_.name(), 0, 0);
  glVertexArrayBindingDivisor(vertex_array_.name(), 0, 1);
}

void PointRaster::upload(const std::vector<pointgen::PointDraw>& draws, const pointgen::TableList& tables,
                         const PointSamples& samples) {
  std::vector<glm::uvec4> gpu_draws;
  std::vector<PlantPose> instances;
  std::vector<DrawCommand> commands;
  std::uint64_t first_point = 0;
  for (const pointgen::PointDraw& d : draws) {
    const pointgen::InstanceTable& table = tables[d.table];
    const auto instance = static_cast<GLuint>(instances.size());
    gpu_draws.emplace_back(static_cast<GLuint>(first_point), d.count, samples.first_sample(table.mesh) + d.first, instance);
    commands.push_back({d.count, 1, samples.first_sample(table.mesh) + d.first, instance});
    instances.push_back(plant_pose(table, d.instance));
    first_point += d.count;
  }
  if (first_point > 0x7FFFFFFFu) throw RuntimeFailure("the point raster draws at most 2^31 points at once");
  std::vector<GLuint> instance_indices(instances.size());
  std::iota(instance_indices.begin(), instance_indices.end(), 0u);
  // Immutable storage is made once per buffer: replace the buffers.
  draws_ = gl::Buffer();
  instances_ = gl::Buffer();
  commands_ = gl::Buffer();
  instance_indices_ = gl::Buffer();
  gl::store(draws_, gpu_draws);
  gl::store(instances_, instances);
  instance_texels_ = gl::buffer_texels(instances_);
  gl::store(commands_, commands);
  gl::store(instance_indices_, instance_indices);
  glVertexArrayVertexBuffer(vertex_array_.name(), 0, instance_indices_.name(), 0, sizeof(GLuint));
  total_points_ = first_point;
  draw_count_ = draws.size();
  samples_ = &samples;
}

void PointRaster::begin(const glm::mat4& view_projection, bool indirect) {
  const float clear_color[4] = {0.0f, 0.0f, 0.0f, 0.0f}, far_depth = 1.0f;
  glClearNamedFramebufferfv(framebuffer_.name(), GL_COLOR, 0, clear_color);
  glClearNamedFramebufferfv(framebuffer_.name(), GL_DEPTH, 0, &far_depth);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.name());
  glViewport(0, 0, size_.x, size_.y);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_PROGRAM_POINT_SIZE);
  glPointSize(1.0f);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, draws_binding, draws_.name());
  glBindTextureUnit(instance_texels_unit, instance_texels_.name());
  if (samples_ != nullptr) samples_->bind();
  gl::set_uniform(program_, "view_projection", view_projection);
  gl::set_uniform(program_, "draw_count", static_cast<unsigned>(draw_count_));
  gl::set_uniform(program_, "indirect", indirect ? 1 : 0);
  glUseProgram(program_.name());
  glBindVertexArray(vertex_array_.name());
}

void PointRaster::draw_all(const glm::mat4& view_projection) {
  begin(view_projection, false);
  if (total_points_ > 0) glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(total_points_));
}

void PointRaster::draw_indirect(const glm::mat4& view_projection) {
  begin(view_projection, true);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.name());
  if (draw_count_ > 0) glMultiDrawArraysIndirect(GL_POINTS, nullptr, static_cast<GLsizei>(draw_count_), 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

Image<float> PointRaster::read_depth() const {
  std::vector<float> bottom_up(static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.name());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size_.x, size_.y, GL_DEPTH_COMPONENT, GL_FLOAT, bottom_up.data());
  return from_bottom_up(size_.x, size_.y, 1, bottom_up);
}

}  // namespace ecoview
