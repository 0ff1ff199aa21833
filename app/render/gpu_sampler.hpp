#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/point_samples.hpp"
#include "app/render/point_splat.hpp"
#include "pointgen/sampling/view_sampler.hpp"

#include <vector>

namespace ecoview {

// The view sampler's per-plant choice on the GPU: the plants of point meshes stay in GL buffers
// from load on (transform, tint, mesh, rounding threshold), and each sample() culls every one
// against the view's frusta, counts it with the density formula, chooses points or polygons with
// the band around break-even, and writes the frame's point draws in plant order, as PointSplat
// reads them, with no read-back. It chooses as pointgen::sample_view does without occlusion, by
// whole plants and without cells' aggregates: the CPU sampler is its test oracle.
class GpuSampler {
 public:
  // `tables` are the scene's groups; only those of point meshes (`samples` has lists for them)
  // become plants, in table order.
  GpuSampler(const std::vector<pointgen::InstanceTable>& tables, const PointSamples& samples);

  // The view's first and only frusta list, eye, density and point cost are used; occlusion, the
  // cap and receivers are not.
  void sample(const pointgen::SamplerView& view);

  // The draws of the last sample(), for PointSplat::use.
  PointDrawList draw_list() const { return {draws_.name(), instances_.name(), block_draws_.name(), totals_.name(), point_capacity_}; }

  std::size_t plant_count() const { return plant_count_; }
  // The plant index of a table's first instance (tables of other meshes hold none).
  std::uint32_t first_plant(std::size_t table) const { return first_plant_[table]; }

  // Read back, for tests and for figures a frame late: per plant (points, 1 when drawn as
  // polygons), and the draws (first point, count, first sample, plant) of the last sample().
  std::vector<glm::uvec2> read_counts() const;
  std::vector<glm::uvec4> read_draws() const;

 private:
  std::size_t plant_count_ = 0;
  std::size_t group_count_ = 0;
  std::size_t point_capacity_ = 0;  // points the draw list has room for
  std::vector<std::uint32_t> first_plant_;
  gl::Buffer instances_, plant_meshes_, meshes_, counts_, offsets_, group_sums_, draws_, block_draws_, totals_;
  gl::Program count_program_, groups_program_, draws_program_;
};

}  // namespace ecoview
