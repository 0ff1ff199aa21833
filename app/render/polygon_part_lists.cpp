#include "app/render/polygon_part_lists.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"

#include <algorithm>
#include <bit>
#include <numeric>

namespace ecoview {
namespace {

constexpr GLuint part_masks_binding = 26, part_plants_binding = 27, part_commands_binding = 29, layer_counts_binding = 31,
                 layer_plants_binding = 32, layer_commands_binding = 33;
constexpr std::size_t command_uints = GpuScene::command_bytes / sizeof(GLuint);
// A table's draws of a list: one per polygon part, one of the plants drawn whole
// (shaders/polygon_parts.glsl).
constexpr std::size_t part_lanes = 65;
// Room in each list: a plant takes a place per part it draws (at most 64), and a frame's polygon
// plants are the few near ones not hidden.
constexpr std::size_t most_part_plants = std::size_t{1} << 22;

template <class T>
void storage(gl::Buffer& buffer, std::size_t count) {
  glNamedBufferStorage(buffer.name(), static_cast<GLsizeiptr>(std::max<std::size_t>(count, 1) * sizeof(T)), nullptr, 0);
}

}  // namespace

PolygonPartLists::PolygonPartLists(std::size_t plant_count, std::size_t table_count, int max_bands)
    : table_count_(table_count),
      capacity_(std::min(most_part_plants, 64 * plant_count)),
      part_masks_program_(gl::build_program({"part_masks.comp"})),
      part_lists_program_(gl::build_program({"part_lists.comp"})),
      layer_start_program_(gl::build_program({"layer_casters.comp"}, "#define START\n")),
      layer_plants_program_(gl::build_program({"layer_casters.comp"})),
      layer_place_program_(gl::build_program({"layer_casters.comp"}, "#define PLACE\n")),
      frame_drawn_(static_cast<std::size_t>(max_bands), table_count * part_lanes),
      layer_drawn_(max_layers, table_count * part_lanes) {
  const std::size_t tables = std::max<std::size_t>(table_count, 1);
  storage<glm::uvec2>(part_masks_, plant_count);
  storage<GLuint>(part_plants_, capacity_);
  storage<GLuint>(part_commands_, command_uints * part_lanes * static_cast<std::size_t>(max_bands) * tables);
  storage<GLuint>(layer_counts_, 4 + 2 * part_lanes * table_count);  // a dispatch, then the counts
  storage<GLuint>(layer_plants_, capacity_);
  storage<GLuint>(layer_commands_, command_uints * part_lanes * max_layers * tables);
  const auto tables_uniform = static_cast<unsigned>(table_count);
  for (const gl::Program* program : {&part_lists_program_, &layer_start_program_, &layer_plants_program_, &layer_place_program_}) {
    gl::set_uniform(*program, "table_count", tables_uniform);
  }
  gl::set_uniform(part_lists_program_, "part_plant_capacity", static_cast<unsigned>(capacity_));
  gl::set_uniform(layer_place_program_, "capacity", static_cast<unsigned>(capacity_));
}

void PolygonPartLists::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, part_masks_binding, part_masks_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, part_plants_binding, part_plants_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, part_commands_binding, part_commands_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layer_counts_binding, layer_counts_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layer_plants_binding, layer_plants_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layer_commands_binding, layer_commands_.name());
}

void PolygonPartLists::begin(const glm::mat4& view_projection, glm::vec2 pixels) {
  selected_layers_ = 0;
  selections_ = 0;
  gl::set_uniform(part_masks_program_, "view_projection", view_projection);
  gl::set_uniform(part_masks_program_, "pixels", pixels);
}

void PolygonPartLists::choose(int band, const DepthPyramid* occluders, GLuint band_dispatch) {
  const auto number = static_cast<unsigned>(band + 1);
  const auto dispatch_at = [&](int which) { return static_cast<GLintptr>((4 * band + which) * sizeof(glm::uvec4)); };
  gl::set_uniform(part_masks_program_, "band_number", number);
  gl::set_uniform(part_masks_program_, "occlusion", occluders ? 1 : 0);
  if (occluders) occluders->bind_for(part_masks_program_);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, band_dispatch);
  glUseProgram(part_masks_program_.name());
  glDispatchComputeIndirect(dispatch_at(3));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  gl::set_uniform(part_lists_program_, "band_number", number);
  gl::set_uniform(part_lists_program_, "first_command", static_cast<unsigned>(static_cast<std::size_t>(band) * table_count_ * part_lanes));
  glUseProgram(part_lists_program_.name());
  glDispatchComputeIndirect(dispatch_at(2));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
  const std::size_t commands = table_count_ * part_lanes;
  frame_drawn_.keep_drawn(part_commands_.name(), static_cast<std::size_t>(band) * commands, commands, static_cast<std::size_t>(band));
}

GpuScene::PlantDraws PolygonPartLists::frame_draws(int band, GLuint plants) const {
  const std::size_t commands = table_count_ * part_lanes;
  return frame_drawn_.from_copy({plants, part_plants_.name(), part_commands_.name(), static_cast<std::size_t>(band) * commands, commands},
                                static_cast<std::size_t>(band));
}

GpuScene::PlantDraws PolygonPartLists::select(int layer, const glm::mat4& map_view, int map_size, const DepthPyramid& receivers,
                                              GLuint plants) {
  if (layer < 0 || layer >= max_layers) throw RuntimeFailure("the GPU sampler selects casters for at most 8 shadow views");
  ++selections_;
  const bool again = (selected_layers_ >> layer) & 1u;
  selected_layers_ |= 1u << layer;
  const std::size_t commands = table_count_ * part_lanes;
  gl::set_uniform(layer_place_program_, "first_command", static_cast<unsigned>(static_cast<std::size_t>(layer) * commands));
  gl::set_uniform(layer_plants_program_, "pixels", glm::vec2(static_cast<float>(map_size)));
  gl::set_uniform(layer_plants_program_, "map_view_projection", map_view);
  receivers.bind_for(layer_plants_program_);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(layer_start_program_.name());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  // Counted, places given, then listed: the plants pass runs twice over the same dispatch.
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, layer_counts_.name());
  glUseProgram(layer_plants_program_.name());
  gl::set_uniform(layer_plants_program_, "writing", 0);
  glDispatchComputeIndirect(0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(layer_place_program_.name());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(layer_plants_program_.name());
  gl::set_uniform(layer_plants_program_, "writing", 1);
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
  const auto list = static_cast<std::size_t>(layer);
  layer_drawn_.keep_drawn(layer_commands_.name(), list * commands, commands, list, again);
  return layer_drawn_.from_copy({plants, layer_plants_.name(), layer_commands_.name(), list * commands, commands}, list);
}

std::size_t PolygonPartLists::frame_triangles(int bands) const {
  const std::vector<std::size_t> per_band = frame_drawn_.read_triangles();
  return std::accumulate(per_band.begin(), per_band.begin() + std::clamp<std::ptrdiff_t>(bands, 0, static_cast<std::ptrdiff_t>(per_band.size())),
                         std::size_t{0});
}

std::vector<std::size_t> PolygonPartLists::layer_triangles() const {
  std::vector<std::size_t> triangles = layer_drawn_.read_triangles();
  triangles.resize(static_cast<std::size_t>(std::bit_width(selected_layers_)));  // layers 0 to the last selected
  return triangles;
}

}  // namespace ecoview
