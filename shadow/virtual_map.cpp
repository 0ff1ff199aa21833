#include "shadow/virtual_map.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace shadow {

std::uint32_t VirtualMap::pages_per_view() const { return level_offset(levels); }

std::uint32_t VirtualMap::level_offset(int level) const {
  std::uint32_t offset = 0;
  for (int l = 0; l < level; ++l) offset += static_cast<std::uint32_t>(pages_per_side(l) * pages_per_side(l));
  return offset;
}

std::uint32_t VirtualMap::id(const Page& p) const {
  return static_cast<std::uint32_t>(p.view) * pages_per_view() + level_offset(p.level) +
         static_cast<std::uint32_t>(p.y * pages_per_side(p.level) + p.x);
}

Page VirtualMap::page(std::uint32_t id) const {
  Page p;
  p.view = static_cast<int>(id / pages_per_view());
  std::uint32_t rest = id % pages_per_view();
  while (p.level + 1 < levels && rest >= level_offset(p.level + 1) - level_offset(p.level)) {
    rest -= level_offset(p.level + 1) - level_offset(p.level);
    ++p.level;
  }
  const auto side = static_cast<std::uint32_t>(pages_per_side(p.level));
  p.x = static_cast<int>(rest % side);
  p.y = static_cast<int>(rest / side);
  return p;
}

std::vector<glm::ivec2> VirtualMap::window_origins(const std::vector<ShadowView>& views, const glm::vec3& eye) const {
  std::vector<glm::ivec2> origins;
  for (const ShadowView& view : views) {
    const glm::vec4 clip = view.clip(eye);
    const glm::vec2 at = clip.w > 0.0f ? glm::clamp(glm::vec2(clip) / clip.w, -1.0f, 1.0f) * 0.5f + 0.5f : glm::vec2(0.5f);
    for (int level = 0; level < levels; ++level) {
      const int side = pages_per_side(level);
      const glm::ivec2 page = glm::min(glm::ivec2(at * static_cast<float>(side)), side - 1);
      origins.push_back(glm::clamp(page - window_pages(level) / 2, 0, side - window_pages(level)));
    }
  }
  return origins;
}

Page VirtualMap::slot_page(std::uint32_t slot, const std::vector<glm::ivec2>& origins) const {
  const auto side = static_cast<std::uint32_t>(window);
  const std::uint32_t grid = slot / (side * side);
  const glm::ivec2 origin = origins[grid];
  return {static_cast<int>(grid) / levels, static_cast<int>(grid) % levels, origin.x + static_cast<int>(slot % side),
          origin.y + static_cast<int>(slot / side % side)};
}

std::optional<std::uint32_t> VirtualMap::slot(const Page& p, const std::vector<glm::ivec2>& origins) const {
  const std::size_t grid = static_cast<std::size_t>(p.view * levels + p.level);
  if (grid >= origins.size()) return std::nullopt;
  const glm::ivec2 at = glm::ivec2(p.x, p.y) - origins[grid];
  if (glm::any(glm::lessThan(at, glm::ivec2(0))) || glm::any(glm::greaterThanEqual(at, glm::ivec2(window_pages(p.level))))) {
    return std::nullopt;
  }
  return static_cast<std::uint32_t>((grid * static_cast<std::size_t>(window) + static_cast<std::size_t>(at.y)) * static_cast<std::size_t>(window) +
                                    static_cast<std::size_t>(at.x));
}

// The tile's map starts `guard` texels before its first page; a level's texel is 2 / its texels
// a side in the base view's normalized coordinates. The crop is a scale and shift of clip x and y.
ShadowView VirtualMap::tile_view(const ShadowView& base, const PageTile& tile, int texels) const {
  const float texel = 2.0f / static_cast<float>(pages_per_side(tile.level) * page_texels);
  const float scale = 2.0f / (static_cast<float>(texels) * texel);
  const glm::vec2 start = glm::vec2(-1.0f) + texel * glm::vec2(static_cast<float>(tile.x * page_texels - guard),
                                                               static_cast<float>(tile.y * page_texels - guard));
  glm::mat4 crop(1.0f);
  crop[0][0] = scale;
  crop[1][1] = scale;
  crop[3][0] = -1.0f - start.x * scale;
  crop[3][1] = -1.0f - start.y * scale;
  return ShadowView(base.view, crop * base.projection);
}

glm::ivec2 VirtualMap::page_corner(const PageTile& tile, const Page& page) const {
  return {(page.x - tile.x) * page_texels, (page.y - tile.y) * page_texels};
}

glm::vec4 image_bounds(const ShadowView& view, const Box& box) {
  glm::vec2 low(1.0f), high(-1.0f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 clip = view.clip(box.corner(i));
    if (clip.w <= 0.0f) return {-1.0f, -1.0f, 1.0f, 1.0f};
    low = glm::min(low, glm::vec2(clip) / clip.w);
    high = glm::max(high, glm::vec2(clip) / clip.w);
  }
  return {low, high};
}

std::vector<PageTile> tiles_of(const std::vector<Page>& pages, int tile_pages) {
  // Per view, level and aligned block: the pages' bounds within it.
  std::map<std::tuple<int, int, int, int>, glm::ivec4> blocks;
  for (const Page& p : pages) {
    const auto key = std::make_tuple(p.view, p.level, p.x / tile_pages, p.y / tile_pages);
    auto [it, added] = blocks.try_emplace(key, glm::ivec4(p.x, p.y, p.x, p.y));
    if (!added) it->second = glm::ivec4(glm::min(glm::ivec2(it->second), glm::ivec2(p.x, p.y)),
                                        glm::max(glm::ivec2(it->second.z, it->second.w), glm::ivec2(p.x, p.y)));
  }
  std::vector<PageTile> tiles;
  for (const auto& [key, bounds] : blocks) {
    tiles.push_back({std::get<0>(key), std::get<1>(key), bounds.x, bounds.y, bounds.z - bounds.x + 1, bounds.w - bounds.y + 1});
  }
  return tiles;
}

}  // namespace shadow
