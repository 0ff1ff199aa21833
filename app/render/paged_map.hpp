#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/frame_pass.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"
#include "shadow/page_pool.hpp"
#include "shadow/shadow_setup.hpp"
#include "shadow/virtual_map.hpp"

#include <optional>
#include <vector>

namespace ecoview {

// The GL side of a virtual paged map (shadow::Lookup::pages, --method adaptive): the layers its
// pages are drawn into (a depth-texture array like ShadowPass's, one page and its guard a layer),
// the page table the frame's lighting reads, and the frame's requests. A frame asks for its
// pages after drawing its surfaces; the renderer draws those to_draw() lists in tiles (each a view
// of shadow::VirtualMap::tile_view, into a ShadowPass layer) and copies them here.
class PagedMap {
 public:
  // `layers` pages (the pool); `depth_format`: the shadow pass's, whose layers pages are copied from;
  // with `silhouettes`, each page's silhouette points beside its depths (SilhouettePass's format).
  PagedMap(const shadow::VirtualMap& map, int layers, GLenum depth_format, bool silhouettes);
  // The pages the frame's surfaces ask for, one virtual map a view of `setup`, given layers; where
  // the views changed since the last frame every page is drawn again. The levels' windows follow
  // the camera. Where `points_follow_camera` (the casters include point-drawn plants, chosen for
  // the camera), pages drawn from a camera far enough from this one are drawn again.
  void request(const FramePass& frame, const shadow::Camera& camera, const shadow::Light& light, const shadow::ShadowSetup& setup,
               bool points_follow_camera);
  // Pages whose casters moved are drawn again when next asked for: those of a view over any of
  // the light-space boxes `moved` (per view, in its normalized coordinates, xy min and max).
  void invalidate(const std::vector<std::vector<glm::vec4>>& moved);
  // What the last request() left to draw, and its figures.
  const shadow::PagePool::Frame& last_request() const { return frame_; }
  // Copies the pages of `tile` that were to be drawn from layer 0 of `tile_map` (a depth-texture
  // array of this depth format), where the tile's view drew them, and with silhouettes their points
  // from layer 0 of `tile_silhouettes`.
  void copy_pages(GLuint tile_map, GLuint tile_silhouettes, const shadow::PageTile& tile) const;
  // The page table, for the lighting after every tile is drawn.
  FramePass::ShadowLookup lookup(const shadow::ShadowSetup& setup);
  const shadow::VirtualMap& map() const { return map_; }
  // The most layers this driver gives a texture array.
  static int most_layers();

 private:
  void upload_table(int views);

  shadow::VirtualMap map_;
  shadow::PagePool pool_;
  shadow::PagePool::Frame frame_;
  std::vector<shadow::ShadowView> views_;  // of the last request
  std::vector<glm::ivec2> origins_;         // its levels' windows (VirtualMap::window_origins)
  gl::Texture pages_{GL_TEXTURE_2D_ARRAY};
  std::optional<gl::Texture> silhouettes_;  // each page's silhouette points in its layer, where the method has them
  gl::Texture table_{GL_TEXTURE_2D_ARRAY};  // a layer a view's level: its window's pages
  gl::Buffer flags_, list_;
  std::vector<GLuint> zeros_;  // the flags as each request starts
};

}  // namespace ecoview
