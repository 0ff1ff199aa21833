#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/gpu_scene.hpp"

#include <cstddef>
#include <vector>

namespace ecoview {

// Lists of indirect draws made on the GPU, copied without their empty draws, with each copy's
// number of draws (for glMultiDrawElementsIndirectCount) and of triangles in a buffer
// (shaders/drawn_commands.comp): the GPU sampler's lists hold a draw per table and part lane,
// most of them empty (82 tables × 65 lanes a band on the ecosystem, some 75,000 draws a frame),
// and a driver walks every draw it is given.
class DrawnCommands {
 public:
  // Room for `lists` copies of up to `commands_per_list` draws each.
  DrawnCommands(std::size_t lists, std::size_t commands_per_list);
  // Copies `count` commands of buffer `commands` from `first`, less the empty ones, into copy
  // `list` (below `lists`), on the GPU; with `adds_triangles` its triangles are added to those
  // the copy counted before (lists drawn in turn from one copy).
  void keep_drawn(GLuint commands, std::size_t first, std::size_t count, std::size_t list, bool adds_triangles = false) const;
  // `draws`, the list that keep_drawn copied as `list`, drawn from that copy.
  GpuScene::PlantDraws from_copy(GpuScene::PlantDraws draws, std::size_t list) const;
  // The triangles each copy draws (or drew, added up), read back.
  std::vector<std::size_t> read_triangles() const;

 private:
  std::size_t lists_ = 0, commands_per_list_ = 0;
  gl::Buffer commands_, counts_;
  gl::Program program_;
};

}  // namespace ecoview
