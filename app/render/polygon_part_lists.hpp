#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/depth_pyramid.hpp"
#include "app/render/drawn_commands.hpp"
#include "app/render/gpu_scene.hpp"

#include <cstdint>
#include <vector>

namespace ecoview {

// The GPU sampler's lists of its polygon plants by part (shaders/polygon_parts.glsl), made on the
// GPU: per band the frame shows, of a plant whose box covers more than 1,024 pixels, the parts
// that nearer bands leave to be seen (shaders/part_masks.comp, part_lists.comp); per shadow view,
// the polygon plants that shadow its receivers, and of a large one the parts that do
// (shaders/layer_casters.comp). Per table an indirect draw per part and one of the plants drawn
// whole. Its passes read the sampler's buffers (counts, bands, tables), which GpuSampler binds.
class PolygonPartLists {
 public:
  PolygonPartLists(std::size_t plant_count, std::size_t table_count, int max_bands);
  static constexpr int max_layers = 8;

  void bind() const;
  // For a frame through `view_projection` (its first view's) onto `pixels`.
  void begin(const glm::mat4& view_projection, glm::vec2 pixels);
  // The frame's lists for `band`, after the sampler counted and listed it; occlusion by
  // `occluders` where given. `band_dispatch`: the sampler's dispatches, three a band (the second:
  // a group per 256 of its plants; the third: a group per lane, or none without polygon plants).
  void choose(int band, const DepthPyramid* occluders, GLuint band_dispatch);
  GpuScene::PlantDraws frame_draws(int band, GLuint plants) const;
  // The lists of the polygon plants of every band this frame that shadow what shadow view
  // `layer` (below max_layers) serves, through `map_view` (its world → clip matrix) onto
  // `map_size`² texels, by the receivers in `receivers`. Views drawn in turn may share a layer:
  // its triangles are then their sum.
  GpuScene::PlantDraws select(int layer, const glm::mat4& map_view, int map_size, const DepthPyramid& receivers, GLuint plants);

  // Read back: the triangles of the frame's first `bands` bands, and of each layer selected for.
  std::size_t frame_triangles(int bands) const;
  std::vector<std::size_t> layer_triangles() const;
  // The selections this frame, over all layers.
  int selections() const { return selections_; }

 private:
  std::size_t table_count_ = 0;
  std::size_t capacity_ = 0;  // places in each list of plants by part
  std::uint32_t selected_layers_ = 0;  // this frame, a bit a layer
  int selections_ = 0;                 // this frame, over all layers
  gl::Buffer part_masks_, part_plants_, part_commands_;
  gl::Program part_masks_program_, part_lists_program_;
  gl::Buffer layer_counts_, layer_plants_, layer_commands_;
  gl::Program layer_start_program_, layer_plants_program_, layer_place_program_;
  DrawnCommands frame_drawn_, layer_drawn_;  // the non-empty draws, per band and per layer
};

}  // namespace ecoview
