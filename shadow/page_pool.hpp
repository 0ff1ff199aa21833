#pragma once
#include "shadow/virtual_map.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

namespace shadow {

// The layers that hold a virtual map's pages (--page-pool): given to the pages a frame asks for
// and kept for the frames after it, which draw again only the pages they had no layer for or whose
// casters moved. Where the pool runs short, the least recently asked-for pages give up their
// layers first, and the finest pages asked for go without: the lookup takes a coarser level there.
class PagePool {
 public:
  PagePool(const VirtualMap& map, int layers);

  struct Frame {
    std::vector<std::pair<Page, int>> to_draw;  // pages and the layers to draw them into
    int requested = 0;  // pages asked for (each once)
    int cached = 0;     // of those, held from an earlier frame as drawn
    int dropped = 0;    // of those, given no layer: the pool was full of this frame's pages
  };
  // Gives each page asked for a layer, coarser levels first; the pages that keep theirs are
  // drawn again only where invalidate() asked. The pages to draw are drawn from `eye`.
  Frame update(const std::vector<std::uint32_t>& requested, const glm::vec3& eye = glm::vec3(0.0f));
  // Pages drawn again when next asked for: those for which `stale` holds, given the eye they were
  // drawn from (their casters moved, or their points were chosen for a camera elsewhere).
  void invalidate(const std::function<bool(const Page&, const glm::vec3& drawn_from)>& stale);
  // Forgets every page (the virtual map's views changed).
  void clear();
  // The layer holding a page, where one does.
  std::optional<int> layer(std::uint32_t id) const;
  // Every page held, and its layer.
  const std::unordered_map<std::uint32_t, int>& held() const { return held_; }
  int layers() const { return static_cast<int>(slots_.size()); }

 private:
  struct Slot {
    std::optional<std::uint32_t> page;
    std::uint64_t last_asked = 0;
    bool drawn = false;
    glm::vec3 drawn_from{0.0f};
  };
  VirtualMap map_;
  std::vector<Slot> slots_;
  std::unordered_map<std::uint32_t, int> held_;  // page id → layer
  std::uint64_t frame_ = 0;
};

}  // namespace shadow
