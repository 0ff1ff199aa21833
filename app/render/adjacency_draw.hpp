#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/gpu_scene.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ecoview {

// Draws the polygon casters with each triangle's neighbours (GL_TRIANGLES_ADJACENCY), for the
// geometry shaders that find silhouette edges (shadow volumes, silhouette maps): the scene's
// instance tables (GpuScene::draw_with_adjacency) with one build of the shader stages, and the
// plants the GPU sampler chose as polygons (GpuScene::draw_chosen_with_adjacency) with another,
// PLANT_INDEX, from a copy of their draws made on the GPU (shaders/adjacency_commands.comp).
class AdjacencyDraw {
 public:
  // `defines` for every build of the stages (SURFACE_TEXTURES where they read materials).
  explicit AdjacencyDraw(std::vector<std::string> stages, std::string defines = {});
  // `scene` with its neighbours found (GpuScene::add_adjacency), the chunks of its large meshes
  // that reach `view` if one is given; `plants`, if any, its plants drawn as polygons
  // (GpuScene::draw_chosen). Each program is bound and handed to `set_uniforms` before it draws.
  void draw(const GpuScene& scene, const GpuScene::PlantDraws* plants,
            const std::function<void(const gl::Program&)>& set_uniforms, const std::optional<glm::mat4>& view = std::nullopt);

 private:
  GpuScene::PlantDraws adjacency_draws(const GpuScene::PlantDraws& plants);

  std::vector<std::string> stages_;
  std::string defines_;
  gl::Program tables_program_;
  std::optional<gl::Program> plants_program_, commands_program_;  // built for the first plants
  gl::Buffer commands_;
  std::size_t capacity_ = 0;  // commands_'s room, in draws
};

}  // namespace ecoview
