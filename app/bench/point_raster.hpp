#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/image.hpp"
#include "app/render/point_samples.hpp"
#include "pointgen/table_list.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace ecoview {

// Point samples drawn by the rasterizer as one-pixel GL_POINTS into a colour + depth target of
// width x height pixels, depth tested: the alternatives to PointSplat's compute shaders, for the
// splat-path benchmark (splat_paths.hpp). Same input as PointSplat::upload.
class PointRaster {
 public:
  explicit PointRaster(glm::ivec2 size);

  void upload(const std::vector<pointgen::PointDraw>& draws, const pointgen::TableList& tables,
              const PointSamples& samples);
  // Clears the target, then draws every point with one glDrawArrays (each vertex finds its draw).
  void draw_all(const glm::mat4& view_projection);
  // Clears the target, then draws with glMultiDrawArraysIndirect, one command per drawn instance.
  void draw_indirect(const glm::mat4& view_projection);

  // Window depth per pixel, 1 where no point landed; rows from the top.
  Image<float> read_depth() const;
  std::size_t point_count() const { return total_points_; }

 private:
  void begin(const glm::mat4& view_projection, bool indirect);

  glm::ivec2 size_;
  std::size_t total_points_ = 0, draw_count_ = 0;
  gl::Texture color_{GL_TEXTURE_2D}, depth_{GL_TEXTURE_2D};
  gl::Framebuffer framebuffer_;
  gl::Program program_;
  gl::VertexArray vertex_array_;
  gl::Buffer draws_, instances_, commands_, instance_indices_;
  gl::Texture instance_texels_{GL_TEXTURE_BUFFER};
  const PointSamples* samples_ = nullptr;
};

}  // namespace ecoview
