#include "app/render/adjacency_draw.hpp"

#include "app/gl/shader_program.hpp"

namespace ecoview {
namespace {

constexpr GLuint commands_binding = 41, adjacent_binding = 42, draw_counts_binding = 43;  // shaders/adjacency_commands.comp

}  // namespace

AdjacencyDraw::AdjacencyDraw(std::vector<std::string> stages, std::string defines)
    : stages_(std::move(stages)), defines_(std::move(defines)), tables_program_(gl::build_program(stages_, defines_)) {}

void AdjacencyDraw::draw(const GpuScene& scene, const GpuScene::PlantDraws* plants,
                         const std::function<void(const gl::Program&)>& set_uniforms, const std::optional<glm::mat4>& view) {
  glUseProgram(tables_program_.name());
  set_uniforms(tables_program_);
  scene.draw_with_adjacency(view);
  if (plants == nullptr || plants->command_count == 0) return;
  const GpuScene::PlantDraws draws = adjacency_draws(*plants);
  if (!plants_program_) plants_program_ = gl::build_program(stages_, defines_ + "#define PLANT_INDEX\n");
  glUseProgram(plants_program_->name());
  set_uniforms(*plants_program_);
  scene.draw_chosen_with_adjacency(draws);
}

GpuScene::PlantDraws AdjacencyDraw::adjacency_draws(const GpuScene::PlantDraws& plants) {
  if (!commands_program_) commands_program_ = gl::build_program({"adjacency_commands.comp"});
  if (plants.command_count > capacity_) {
    capacity_ = plants.command_count;
    commands_ = gl::Buffer();
    glNamedBufferStorage(commands_.name(), static_cast<GLsizeiptr>(capacity_ * GpuScene::command_bytes), nullptr, 0);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, commands_binding, plants.commands);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, adjacent_binding, commands_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, draw_counts_binding, plants.draw_counts);
  glUseProgram(commands_program_->name());
  gl::set_uniform(*commands_program_, "first_command", static_cast<unsigned>(plants.first_command));
  gl::set_uniform(*commands_program_, "command_count", static_cast<unsigned>(plants.command_count));
  gl::set_uniform(*commands_program_, "count_slot", static_cast<unsigned>(plants.count_slot));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((plants.command_count + 63) / 64), 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  GpuScene::PlantDraws draws = plants;
  draws.commands = commands_.name();
  draws.first_command = 0;
  return draws;
}

}  // namespace ecoview
