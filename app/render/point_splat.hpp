#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/image.hpp"
#include "app/render/point_samples.hpp"
#include "pointgen/table_list.hpp"

#include <memory>
#include <vector>

namespace ecoview {

// A frame's point draws in GL buffers, wherever they were made (PointSplat::upload on the CPU,
// GpuSampler on the GPU): per draw its points (first point, count) and in a second buffer its
// samples (first sample, instance; shaders/point_draws.glsl), the instances
// (model matrix, tint) as a buffer texture (shaders/plant_instances.glsl), per block of 16 points
// the draw holding its first point, and the totals (points, draws, where the band last added
// begins) as three uints, so that a list made on the GPU is drawn without a read-back.
struct PointDrawList {
  GLuint draw_points = 0, draw_samples = 0, instance_texels = 0, block_draws = 0, totals = 0;
  std::size_t most_points = 0;  // the most points the list may hold
  // A GpuSampler's list: per draw the most points a shadow map takes of it (GpuSampler::cap_for_map).
  // None for others.
  GLuint map_caps = 0;
};

// Point splatting with compute shaders into a target of width x height pixels: the frame's draws
// go to GL buffers; pass 1 keeps each pixel's nearest depth (atomicMin), pass 2 the nearest point
// and the nearest of those centred in the pixel (for shading), from where pass 1 put each point
// rather than projecting it again (on llvmpipe a third of the time). 32-bit atomics only, so it runs on llvmpipe as on any GL 4.5 driver.
class PointSplat {
 public:
  explicit PointSplat(glm::ivec2 size);

  // The points to draw: the first `count` samples of each drawn instance.
  void upload(const std::vector<pointgen::PointDraw>& draws, const pointgen::TableList& tables,
              const PointSamples& samples);
  // Or a list already in GL buffers, which must outlive its use here.
  void use(const PointDrawList& list, const PointSamples& samples);
  // Passes 1 and 2, with splats of splat_size x splat_size pixels, for shading.
  void splat(const glm::mat4& view_projection, int splat_size, float depth_bias);
  // The same in steps, for a list made band by band (GpuSampler): clear; pass 1 over the band
  // last added, or over the whole list, which also adds per pixel the image area of the points in
  // front of the polygons drawn so far (the share of it they cover) as `seen` sees them; then pass
  // 2 over the whole list.
  struct CoverageView {
    glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f};
    float pixels_per_radian = 0.0f;  // the frame's height over 2 tan(fov_y / 2)
    GLuint polygon_depth = 0;        // a depth texture of the target's size; 0: none hides a point
  };
  void begin();
  void add(const glm::mat4& view_projection, int splat_size, float depth_bias, bool band_only, const CoverageView& seen);
  void resolve(const glm::mat4& view_projection, int splat_size, float depth_bias);
  // Per pixel the nearest point's window depth (float bits; all ones where none), after pass 1.
  GLuint depth_buffer() const { return depths_.name(); }
  // Pass 1 onto one layer of a depth-texture array of the target's size (a shadow map): each
  // texel keeps the nearer of its depth and the points'. For a paraboloid shadow view,
  // `view_projection` is its world → light space matrix and `paraboloid` its zoom and range
  // (shadow::Paraboloid); zoom 0 for a projective view. Of a list with map caps, each draw's
  // first points up to its cap.
  void splat_onto(GLuint depth_texture, int layer, const glm::mat4& view_projection, int splat_size, float depth_bias,
                  glm::vec2 paraboloid);
  // The points splat_onto drew of a list with map caps since use() (read back).
  std::size_t points_drawn_onto() const;
  // Per pixel, the points on the surface `surface_depth` shows there (linear view depth, rows from
  // the top, negative where none), each counted once where its centre lands, rows from the top: for
  // the density figures. On the surface: within `surface_gap` of its depth, as a fraction of it.
  // Overwrites the nearest depths and points, so call it after the frame is shaded.
  Image<std::uint32_t> count_points_on(const Image<float>& surface_depth, const glm::mat4& view_projection,
                                       const glm::mat4& projection, float surface_gap);
  // Binds the buffers and sets the target and splat size a shading program reads (the splat size
  // of the last pass 1).
  void bind_for(const gl::Program& program) const;


 private:
  glm::ivec2 size_;
  PointDrawList list_;  // the one drawn: uploaded_ or another's
  gl::Buffer draw_points_, draw_samples_, instances_, block_draws_, totals_, depths_, winners_, projected_, dispatch_, points_drawn_onto_;
  gl::Texture instance_texels_{GL_TEXTURE_BUFFER};  // over instances_, made again with its store
  gl::Buffer coverage_, centre_depths_, centre_winners_;  // point_common.glsl
  std::size_t draw_points_capacity_ = 0, draw_samples_capacity_ = 0, instances_capacity_ = 0, block_draws_capacity_ = 0, projected_capacity_ = 0;
  // Which of the list's points a pass takes: the frame's, those of the band last added, or every
  // one, the shadow maps' alone too.
  enum class Points { frame, last_band, all };
  // The pass's work groups for those points, written on the GPU (shaders/point_dispatch.comp).
  void count_groups(Points points) const;
  // Runs one pass of `program` over them.
  void dispatch(const gl::Program& program, const glm::mat4& view_projection, int splat_size, float depth_bias,
                glm::vec2 paraboloid, Points points) const;

  gl::Program dispatch_program_, depth_program_, keeping_depth_program_, capped_depth_program_, resolve_program_;
  // splat_onto's way back into the map's layer (shaders/map_depth_merge.frag).
  gl::Program merge_program_;
  gl::Framebuffer map_layer_;
  gl::VertexArray no_vertices_;
  std::unique_ptr<gl::Program> count_program_;  // made when first counting
  const PointSamples* samples_ = nullptr;
  int frame_splat_size_ = 1;
};

}  // namespace ecoview
