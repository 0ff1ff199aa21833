#include "app/render/drawn_commands.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"

#include <glm/glm.hpp>

#include <algorithm>

namespace ecoview {
namespace {

constexpr GLuint commands_binding = 41, drawn_binding = 42, drawn_counts_binding = 43;  // shaders/drawn_commands.comp

}  // namespace

DrawnCommands::DrawnCommands(std::size_t lists, std::size_t commands_per_list)
    : lists_(lists), commands_per_list_(commands_per_list), program_(gl::build_program({"drawn_commands.comp"})) {
  glNamedBufferStorage(commands_.name(), static_cast<GLsizeiptr>(std::max<std::size_t>(lists * commands_per_list, 1) * GpuScene::command_bytes),
                       nullptr, 0);
  gl::store(counts_, std::vector<glm::uvec2>(std::max<std::size_t>(lists, 1), glm::uvec2(0)));
}

void DrawnCommands::keep_drawn(GLuint commands, std::size_t first, std::size_t count, std::size_t list, bool adds_triangles) const {
  if (list >= lists_ || count > commands_per_list_) throw RuntimeFailure("a list of draws outgrew its room");
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, commands_binding, commands);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, drawn_binding, commands_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, drawn_counts_binding, counts_.name());
  gl::set_uniform(program_, "first_command", static_cast<unsigned>(first));
  gl::set_uniform(program_, "command_count", static_cast<unsigned>(count));
  gl::set_uniform(program_, "drawn_first", static_cast<unsigned>(list * commands_per_list_));
  gl::set_uniform(program_, "count_slot", static_cast<unsigned>(list));
  gl::set_uniform(program_, "adds_triangles", adds_triangles ? 1 : 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  glUseProgram(program_.name());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

GpuScene::PlantDraws DrawnCommands::from_copy(GpuScene::PlantDraws draws, std::size_t list) const {
  if (list >= lists_ || draws.command_count > commands_per_list_) throw RuntimeFailure("a list of draws outgrew its room");
  draws.commands = commands_.name();
  draws.first_command = list * commands_per_list_;
  draws.draw_counts = counts_.name();
  draws.count_slot = 2 * list;
  return draws;
}

std::vector<std::size_t> DrawnCommands::read_triangles() const {
  std::vector<glm::uvec2> counts(lists_);
  glGetNamedBufferSubData(counts_.name(), 0, static_cast<GLsizeiptr>(counts.size() * sizeof(glm::uvec2)), counts.data());
  std::vector<std::size_t> triangles;
  for (const glm::uvec2& c : counts) triangles.push_back(c.y);
  return triangles;
}

}  // namespace ecoview
