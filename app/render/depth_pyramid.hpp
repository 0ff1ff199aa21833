#pragma once
#include "app/gl/gl_objects.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace ecoview {

// A farthest-depth pyramid over a frame, as GPU-driven renderers cull by: level 0 holds, per
// pixel, the nearest window depth of what is drawn so far within one pixel of it (polygons in a
// depth texture, points in a splat's depth buffer; 1 where nothing is), so that one-pixel gaps
// between leaves and splats count as closed; each level above holds the farthest of the 2 × 2
// texels below. A box whose nearest depth lies beyond the pyramid's farthest over its screen
// rectangle is hidden (shaders/depth_pyramid.glsl).
class DepthPyramid {
 public:
  explicit DepthPyramid(glm::ivec2 size);
  // Rebuilds it from the polygons' depth texture (a depth or depth-stencil texture of the size)
  // and the points' nearest depths (the float bits of window depths, one uint per pixel, all ones
  // where none).
  void build(GLuint polygon_depth, GLuint point_depths) const;
  // Or rebuilds only its tiles of 32 × 32 pixels that passes bound with bind_for marked changed
  // since the last build (shaders/depth_pyramid.glsl, mark_changed), and the levels above them
  // where any was; decided on the GPU without a read-back.
  void build_changed(GLuint polygon_depth, GLuint point_depths) const;
  // Or, over a shadow view's image, as a receiver mask: level 0 holds where `frame` (the frame's
  // pyramid, last built) shows a surface through `map_view_projection` the farthest window depth
  // of those surfaces in that view (above 0), 0 elsewhere, and each level above the most of the
  // 2 × 2 below; a caster whose rectangle there holds no depth beyond its own nearest shadows
  // nothing the frame shows. Of a cascade, `earlier` are the cascades before it (at most 8), of
  // maps `map_texels` wide: it marks no surface that looks one of them up.
  void build_receivers(const DepthPyramid& frame, const glm::mat4& frame_view_projection, const glm::mat4& map_view_projection,
                       const std::vector<glm::mat4>& earlier = {}, float map_texels = 1.0f) const;
  // Or as a receiver mask with a receiver at the far end of every texel: a caster is then
  // selected by whether its rectangle reaches the view's image at all (a paged map's tiles, whose
  // pages are kept for later frames that may show other receivers).
  void mark_everywhere() const;
  // Binds it for a program that includes depth_pyramid.glsl, and its changed tiles for one that
  // marks them.
  void bind_for(const gl::Program& program) const;
  // Its levels, the last one texel; a level's texels, rows from the bottom (for tests).
  std::size_t levels() const { return sizes_.size(); }
  std::vector<float> read(std::size_t level) const;
  // Per tile of 32 × 32 pixels, rows from the bottom, whether it is marked changed (for tests).
  std::vector<bool> read_changed_tiles() const;
  glm::ivec2 tile_counts() const;

 private:
  void set_levels(const gl::Program& program) const;
  void fill_marks(float mark) const;  // level 0 of a receiver mask, all `mark`
  // The base over every tile (`whole_image`) or the changed ones, the levels above, and the
  // changed tiles' marks cleared.
  void build_tiles(bool whole_image, GLuint polygon_depth, GLuint point_depths) const;
  // The levels from first_level up, each pass's work groups as `passes` holds them (whole_ or
  // commands_); dispatch runs one pass.
  void reduce(const gl::Buffer& passes, std::size_t first_level) const;
  void dispatch(const gl::Buffer& passes, std::size_t pass) const;
  glm::ivec2 size_;
  std::vector<glm::ivec2> sizes_;      // per level
  std::vector<GLuint> offsets_;        // per level, in floats
  gl::Buffer depths_;
  gl::Texture depth_texels_{GL_TEXTURE_BUFFER};  // depths_ for the passes that read it (bind_for)
  // The build's passes as indirect dispatches, a uvec4 each: [0] the base's, a work group per
  // tile, [l] level l's from the one below. whole_ holds each over the whole image (the receiver
  // mask's levels read it); commands_ a build's (shaders/pyramid_dispatch.comp): the base over the
  // listed tiles, the levels above whole or not at all, and after them a count of listed tiles.
  gl::Buffer whole_, commands_;
  // Per tile whether it changed since the last build, and the changed ones' numbers.
  gl::Buffer changed_tiles_, changed_list_;
  gl::Program base_program_, reduce_program_, list_program_, dispatch_program_;
  // Made with the pyramid, not with the first frame that marks receivers, so that frame times
  // hold no shader compilation.
  gl::Program clear_marks_program_, marks_program_;
};

}  // namespace ecoview
