#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/adjacency_draw.hpp"
#include "app/render/mask_technique.hpp"

#include <optional>

namespace ecoview {

// Exact shadows of polygon casters by stencil shadow volumes extruded from silhouette edges
// (shaders/shadow_volume.geom), counted against the depth of a drawn frame so that a count of 0
// means lit. z-pass (Heidmann 1991): faces in front of the surface, +1 entering and -1 leaving; it
// needs no far caps, but holds only where the camera stands in no volume. z-fail (Carmack's
// reverse, 2000): faces behind the surface, +1 leaving and -1 entering, with far caps; it holds
// everywhere. The result is a mask of the frame's pixels, 1 where the light reaches the surface.
// Point splats receive through the mask but cast nothing. A count cannot follow an alpha mask, so
// the triangles a mask may cut cast no volume: where their prisms reach, each pixel's ray to the
// light is met with the triangle and its mask (shaders/masked_prism.*).
class ShadowVolumePass {
 public:
  // `depth_stencil`: the frame's GL_DEPTH32F_STENCIL8 texture of width x height. `masked_casters`:
  // whether any caster has an alpha mask.
  ShadowVolumePass(int width, int height, GLuint depth_stencil, bool masked_casters);
  enum class Counting { z_pass, z_fail };
  // The casters are `frame.polygons`, with its neighbours found (GpuScene::add_adjacency), and
  // `frame.plants`, if any: the plants the GPU sampler chose as polygons (GpuScene::draw_chosen).
  void render(const MaskFrame& frame, Counting counting);
  // Hybrid shadows (Chan and Durand 2004): the mask is `visibility` (the frame's R8 `shadow` AOV
  // as a shadow map lit it) where that is 0 or 1, and the volumes' count only where it lies
  // between, near the edges of the map's shadows. The stencil's top bit marks those pixels as the
  // computation mask: the volumes' faces elsewhere fail the stencil test, and counts wrap in the
  // seven bits below it.
  void render_near_edges(const MaskFrame& frame, Counting counting);
  GLuint light_mask() const { return mask_.name(); }

 private:
  // Adds each volume face's +1 or -1 to the stencil where its test passes.
  void count(const MaskFrame& frame, Counting counting);
  // Writes 0 into the mask where a masked triangle shadows the surface and the stencil test passes.
  void shadow_by_masked(const MaskFrame& frame);
  // Writes `value` into the mask where the stencil test passes.
  void write_mask(float value) const;
  void draw_fullscreen() const;  // one triangle over the viewport, the program's own

  int width_, height_;
  gl::Texture mask_{GL_TEXTURE_2D};
  gl::Framebuffer framebuffer_;
  gl::Framebuffer stencil_only_;  // the frame's depth and stencil alone: marks pixels from the mask's source
  AdjacencyDraw volumes_;
  std::optional<AdjacencyDraw> masked_prisms_;  // where any caster is masked
  gl::Program mask_program_;
  gl::Program edge_program_;
  gl::VertexArray empty_vertex_array_;
};

}  // namespace ecoview
