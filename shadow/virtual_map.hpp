#pragma once
#include "shadow/box.hpp"
#include "shadow/shadow_setup.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

// A virtual shadow map paged by what the frame needs (--method adaptive): the adaptive shadow
// maps of Fernando et al. 2001 as production engines page them. Each view of a setup is a virtual
// map of `page_texels` · 2^(levels − 1) texels a side, kept in levels like mipmaps (level l's
// texels are 2^l of the finest's), each level cut into square pages. Only the pages the frame's
// pixels ask for are drawn, each into a layer of its own with `guard` texels of its neighbours
// around it, so that the lookup's filter never leaves the page.
//
// A frame addresses at most `window` pages a side of a level: the window around the page under
// the camera, as clipmaps keep their levels around the viewer. The coarse levels fit whole; the
// fine ones reach only as far as pixels near the camera ask for them, so the page table and the
// requests stay small however fine the finest level is.
namespace shadow {

// A page: which view's virtual map, the level, the column and row (from the map's −x, −y corner).
struct Page {
  int view = 0, level = 0, x = 0, y = 0;
  bool operator==(const Page&) const = default;
};

// Pages of one view and level drawn together: `columns` × `rows` pages from (x, y), with the
// guard around them, drawn into one map (the tile's own view).
struct PageTile {
  int view = 0, level = 0, x = 0, y = 0;
  int columns = 1, rows = 1;
  bool holds(const Page& p) const {
    return p.view == view && p.level == level && p.x >= x && p.y >= y && p.x < x + columns && p.y < y + rows;
  }
};

struct VirtualMap {
  // The finest, 0, has 2^(levels − 1) pages a side; the coarsest one. At most 14: six views'
  // page ids fit in 32 bits, and the shaders hold the windows of 16 levels a view.
  int levels = 12;
  int page_texels = 256;  // a page's own texels a side
  int guard = 4;          // texels of the neighbours around a page, for the filter's taps
  // A pixel asks for the coarsest level whose texels are this many or more to its width there.
  int pixel_texels = 2;
  int window = 128;  // pages a side a frame addresses of each level, around the camera
  // The casters out of the frame's view get points for this many texels a side over the whole
  // map, each tile capping them to its own level: the finest level's would give each such plant
  // its whole sample list.
  float caster_texels = 65536.0f;

  int pages_per_side(int level) const { return 1 << (levels - 1 - level); }
  // Pages a side of a level's window: the whole level where it fits.
  int window_pages(int level) const { return std::min(pages_per_side(level), window); }
  // Where each level's window starts, view by view and level by level: around the page under
  // `eye` in each view's image (the image's centre where the eye is behind a view's centre of
  // projection), inside the level.
  std::vector<glm::ivec2> window_origins(const std::vector<ShadowView>& views, const glm::vec3& eye) const;
  // The frame's slots: a `window` × `window` grid a level, view by view, level by level, row by
  // row; a page's slot is its place in its level's window (`origins` from window_origins).
  std::uint32_t slots_per_view() const { return static_cast<std::uint32_t>(levels * window * window); }
  Page slot_page(std::uint32_t slot, const std::vector<glm::ivec2>& origins) const;
  // The page's slot, where its level's window holds it.
  std::optional<std::uint32_t> slot(const Page& page, const std::vector<glm::ivec2>& origins) const;
  // Texels a side of a page's layer: the page and its guard.
  int layer_texels() const { return page_texels + 2 * guard; }
  // Pages of one view, every level's.
  std::uint32_t pages_per_view() const;
  // The first page of `level` among a view's, level by level from the finest, row by row.
  std::uint32_t level_offset(int level) const;
  // A page's number among every view's (view by view), and back.
  std::uint32_t id(const Page& page) const;
  Page page(std::uint32_t id) const;

  // The view that draws `tile` into a map of `texels` a side: `base` (a projective view of the
  // setup) with its image cropped to the tile's pages and their guard, texel for texel.
  ShadowView tile_view(const ShadowView& base, const PageTile& tile, int texels) const;
  // Where a page of the tile lies in the tile's map: its layer's lower left texel (guard included).
  glm::ivec2 page_corner(const PageTile& tile, const Page& page) const;
  // The most pages a side a tile drawn into a map of `texels` a side holds.
  int tile_pages(int texels) const { return (texels - 2 * guard) / page_texels; }
  // Texels a side of the map tiles are drawn into: four pages a side and their guard. Each tile
  // costs a pass over every caster, and on llvmpipe its map's size too (street, a still camera,
  // 640 × 360: 211 ms of shadow pass a frame in maps of 1024², 350 in 2048², 616 in 4096²).
  int tile_texels() const { return 4 * page_texels + 2 * guard; }
};

// Where a box lies in a projective view's image: its normalized coordinates' xy, min then max;
// the whole image where part of the box is behind the view's centre of projection.
glm::vec4 image_bounds(const ShadowView& view, const Box& box);

// The pages to draw, in tiles of at most `tile_pages` a side, within squares aligned to multiples
// of it: every page in exactly one, each tile the bounds of its pages.
std::vector<PageTile> tiles_of(const std::vector<Page>& pages, int tile_pages);

}  // namespace shadow
