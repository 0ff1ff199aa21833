// The virtual paged map's bookkeeping against facts the test works out itself: page numbers, the
// tiles' views texel for texel, the tiles' cover of the pages, and the pool's keeping, evicting and
// dropping of pages.
#include "shadow/page_pool.hpp"
#include "shadow/virtual_map.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <random>
#include <set>

namespace shadow {
namespace {

VirtualMap small_map() { return {4, 16, 2}; }  // 8 pages a side at level 0, pages of 16 texels

TEST(VirtualMap, EveryPageHasItsOwnNumberAndComesBackFromIt) {
  const VirtualMap map = small_map();
  ASSERT_EQ(map.pages_per_view(), 64u + 16u + 4u + 1u);
  std::set<std::uint32_t> ids;
  for (int view = 0; view < 2; ++view) {
    for (int level = 0; level < map.levels; ++level) {
      for (int y = 0; y < map.pages_per_side(level); ++y) {
        for (int x = 0; x < map.pages_per_side(level); ++x) {
          const Page page{view, level, x, y};
          const std::uint32_t id = map.id(page);
          EXPECT_EQ(map.page(id), page);
          ids.insert(id);
        }
      }
    }
  }
  EXPECT_EQ(ids.size(), 2u * map.pages_per_view());
  EXPECT_EQ(*ids.rbegin(), 2u * map.pages_per_view() - 1u);
}

// A world point at the centre of virtual texel (i, j) of a level lands, through the tile's view,
// at the centre of texel (i, j) less the tile's first page and plus the guard, in the tile's map.
TEST(VirtualMap, ATileViewDrawsItsPagesTexelForTexel) {
  const VirtualMap map = small_map();
  const ShadowView base(glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1)),
                        glm::ortho(-50.0f, 50.0f, -50.0f, 50.0f, 1.0f, 30.0f));
  const int tile_texels = 2 * map.page_texels + 2 * map.guard + 6;
  ASSERT_EQ(map.tile_pages(tile_texels), 2);
  for (int level = 0; level < 3; ++level) {
    const PageTile tile{0, level, map.pages_per_side(level) - 2, 1, 2, 2};
    const ShadowView view = map.tile_view(base, tile, tile_texels);
    const int virtual_texels = map.pages_per_side(level) * map.page_texels;
    for (int i = tile.x * map.page_texels - map.guard; i < (tile.x + 2) * map.page_texels + map.guard; i += 3) {
      const int j = tile.y * map.page_texels + 5;
      // The virtual texel's centre in the base view's normalized coordinates, back to the world.
      const glm::vec2 ndc = (glm::vec2(i, j) + 0.5f) / static_cast<float>(virtual_texels) * 2.0f - 1.0f;
      const glm::vec4 world = glm::inverse(base.view_projection()) * glm::vec4(ndc, 0.0f, 1.0f);
      const glm::vec4 clip = view.view_projection() * world;
      const glm::vec2 texel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * static_cast<float>(tile_texels);
      const glm::vec2 expected = glm::vec2(i - tile.x * map.page_texels + map.guard, j - tile.y * map.page_texels + map.guard) + 0.5f;
      EXPECT_NEAR(texel.x, expected.x, 1e-3f) << "level " << level << ", texel " << i;
      EXPECT_NEAR(texel.y, expected.y, 1e-3f) << "level " << level << ", texel " << i;
    }
    // And a page's layer starts at its guard's first texel.
    EXPECT_EQ(map.page_corner(tile, {0, level, tile.x + 1, tile.y + 1}), glm::ivec2(map.page_texels, map.page_texels));
  }
}

TEST(VirtualMap, TilesHoldEveryPageOnceAndOnlyPagesOfTheirOwnLevel) {
  const VirtualMap map = small_map();
  std::mt19937 rng(3);
  for (int round = 0; round < 50; ++round) {
    std::set<std::uint32_t> asked;
    const int count = static_cast<int>(rng() % 40) + 1;
    for (int i = 0; i < count; ++i) asked.insert(static_cast<std::uint32_t>(rng() % (2 * map.pages_per_view())));
    std::vector<Page> pages;
    for (std::uint32_t id : asked) pages.push_back(map.page(id));
    const int most = 1 + round % 4;
    const std::vector<PageTile> tiles = tiles_of(pages, most);
    for (const Page& p : pages) {
      int holding = 0;
      for (const PageTile& t : tiles) holding += t.holds(p);
      EXPECT_EQ(holding, 1) << "round " << round;
    }
    for (const PageTile& t : tiles) {
      EXPECT_LE(std::max(t.columns, t.rows), most);
      bool first_column = false, first_row = false, last_column = false, last_row = false;
      for (const Page& p : pages) {
        if (!t.holds(p)) continue;
        first_column |= p.x == t.x;
        first_row |= p.y == t.y;
        last_column |= p.x == t.x + t.columns - 1;
        last_row |= p.y == t.y + t.rows - 1;
      }
      EXPECT_TRUE(first_column && first_row && last_column && last_row) << "a tile wider than its pages";
    }
  }
}

std::vector<std::uint32_t> ids_of(const VirtualMap& map, const std::vector<Page>& pages) {
  std::vector<std::uint32_t> ids;
  for (const Page& p : pages) ids.push_back(map.id(p));
  return ids;
}

// Windows of 4 pages a side over levels of 32, 16, 8, 4, 2 and 1: the eye's page is in every
// level's window, each window lies inside its level, and the coarse levels fit whole.
TEST(VirtualMap, EachLevelsWindowHoldsThePageUnderTheEyeAndStaysInsideTheLevel) {
  VirtualMap map{6, 16, 2};
  map.window = 4;
  const ShadowView view(glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1)),
                        glm::ortho(-50.0f, 50.0f, -50.0f, 50.0f, 1.0f, 30.0f));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> across(-60.0f, 60.0f);
  for (int round = 0; round < 200; ++round) {
    const glm::vec3 eye(across(rng), 2.0f, across(rng));
    const std::vector<glm::ivec2> origins = map.window_origins({view}, eye);
    ASSERT_EQ(origins.size(), static_cast<std::size_t>(map.levels));
    const glm::vec4 clip = view.clip(eye);
    const glm::vec2 at = glm::clamp(glm::vec2(clip) / clip.w, -0.999f, 0.999f) * 0.5f + 0.5f;
    for (int level = 0; level < map.levels; ++level) {
      const int side = map.pages_per_side(level);
      const glm::ivec2 origin = origins[static_cast<std::size_t>(level)];
      const glm::ivec2 eye_page(at * static_cast<float>(side));
      EXPECT_TRUE(map.slot({0, level, eye_page.x, eye_page.y}, origins).has_value()) << "level " << level;
      EXPECT_GE(glm::min(origin.x, origin.y), 0);
      EXPECT_LE(glm::max(origin.x, origin.y) + map.window_pages(level), side);
      if (side <= map.window) {
        EXPECT_EQ(origin, glm::ivec2(0));
      }
    }
  }
}

// Every page a window holds has a slot of its own that gives it back; pages outside have none.
TEST(VirtualMap, APageInItsWindowHasASlotThatGivesItBack) {
  VirtualMap map{5, 16, 2};
  map.window = 4;
  const std::vector<glm::ivec2> origins = {{3, 9}, {1, 2}, {0, 0}, {0, 0}, {0, 0},   // view 0, levels 0 to 4
                                           {12, 0}, {4, 4}, {0, 0}, {0, 0}, {0, 0}};  // view 1
  std::set<std::uint32_t> slots;
  int held = 0;
  for (int view = 0; view < 2; ++view) {
    for (int level = 0; level < map.levels; ++level) {
      const glm::ivec2 origin = origins[static_cast<std::size_t>(view * map.levels + level)];
      for (int y = 0; y < map.pages_per_side(level); ++y) {
        for (int x = 0; x < map.pages_per_side(level); ++x) {
          const Page page{view, level, x, y};
          const bool inside = x >= origin.x && y >= origin.y && x < origin.x + map.window && y < origin.y + map.window;
          const std::optional<std::uint32_t> slot = map.slot(page, origins);
          ASSERT_EQ(slot.has_value(), inside) << view << " " << level << " " << x << " " << y;
          if (!slot) continue;
          EXPECT_LT(*slot, 2u * map.slots_per_view());
          EXPECT_EQ(map.slot_page(*slot, origins), page);
          slots.insert(*slot);
          ++held;
        }
      }
    }
  }
  EXPECT_EQ(slots.size(), static_cast<std::size_t>(held));
}

TEST(PagePool, KeepsDrawnPagesForTheFramesThatAskAgain) {
  const VirtualMap map = small_map();
  PagePool pool(map, 8);
  const std::vector<std::uint32_t> asked = ids_of(map, {{0, 0, 1, 1}, {0, 0, 2, 1}, {0, 1, 0, 0}, {0, 3, 0, 0}});
  const PagePool::Frame first = pool.update(asked);
  EXPECT_EQ(first.requested, 4);
  EXPECT_EQ(first.to_draw.size(), 4u);
  EXPECT_EQ(first.cached, 0);
  std::set<int> layers;
  for (const auto& [page, layer] : first.to_draw) layers.insert(layer);
  EXPECT_EQ(layers.size(), 4u) << "two pages in one layer";
  const PagePool::Frame second = pool.update(asked);
  EXPECT_TRUE(second.to_draw.empty());
  EXPECT_EQ(second.cached, 4);
  // Casters moved over one page: it alone is drawn again, into the layer it holds.
  pool.invalidate([](const Page& p, const glm::vec3&) { return p.level == 1; });
  const PagePool::Frame third = pool.update(asked);
  ASSERT_EQ(third.to_draw.size(), 1u);
  EXPECT_EQ(third.to_draw[0].first, (Page{0, 1, 0, 0}));
  EXPECT_EQ(third.to_draw[0].second, *pool.layer(map.id({0, 1, 0, 0})));
  pool.clear();
  EXPECT_EQ(pool.update(asked).to_draw.size(), 4u);
}

// Each page remembers the eye it was last drawn from, which the test of staleness is given.
TEST(PagePool, RemembersTheEyeEachPageWasDrawnFrom) {
  const VirtualMap map = small_map();
  PagePool pool(map, 8);
  const glm::vec3 here(1, 2, 3), there(7, 2, 3), later(9, 2, 3);
  const std::vector<std::uint32_t> one = ids_of(map, {{0, 0, 1, 1}});
  const std::vector<std::uint32_t> both = ids_of(map, {{0, 0, 1, 1}, {0, 2, 1, 0}});
  pool.update(one, here);
  EXPECT_EQ(pool.update(both, there).to_draw.size(), 1u);  // the new page, drawn from `there`
  pool.invalidate([&](const Page&, const glm::vec3& drawn_from) { return drawn_from == here; });
  const PagePool::Frame again = pool.update(both, later);
  ASSERT_EQ(again.to_draw.size(), 1u);
  EXPECT_EQ(again.to_draw[0].first, (Page{0, 0, 1, 1}));
  pool.invalidate([&](const Page& p, const glm::vec3& drawn_from) { return drawn_from == later && p.level == 0; });
  EXPECT_EQ(pool.update(both, later).to_draw.size(), 1u);  // drawn again from `later`, so stale again
}

TEST(PagePool, GivesUpTheLeastRecentlyAskedForPagesFirst) {
  const VirtualMap map = small_map();
  PagePool pool(map, 3);
  const std::uint32_t a = map.id({0, 0, 0, 0}), b = map.id({0, 0, 1, 0}), c = map.id({0, 0, 2, 0}), d = map.id({0, 0, 3, 0});
  pool.update({a, b, c});
  pool.update({a, c});  // b is the least recently asked for
  const PagePool::Frame frame = pool.update({d});
  ASSERT_EQ(frame.to_draw.size(), 1u);
  EXPECT_FALSE(pool.layer(b).has_value());
  EXPECT_TRUE(pool.layer(a).has_value());
  EXPECT_TRUE(pool.layer(c).has_value());
  EXPECT_TRUE(pool.layer(d).has_value());
}

// Where a frame asks for more pages than the pool holds, the coarser ones get layers (they serve
// wherever finer ones are missing) and the finest go without.
TEST(PagePool, DropsTheFinestPagesWhenAFrameAsksForMoreThanItHolds) {
  const VirtualMap map = small_map();
  PagePool pool(map, 3);
  const PagePool::Frame frame = pool.update(ids_of(map, {{0, 0, 0, 0}, {0, 0, 1, 0}, {0, 1, 0, 0}, {0, 2, 0, 0}, {0, 3, 0, 0}}));
  EXPECT_EQ(frame.requested, 5);
  EXPECT_EQ(frame.dropped, 2);
  for (const auto& [page, layer] : frame.to_draw) EXPECT_GE(page.level, 1);
}

}  // namespace
}  // namespace shadow
