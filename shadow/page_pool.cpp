#include "shadow/page_pool.hpp"

#include <algorithm>

namespace shadow {

PagePool::PagePool(const VirtualMap& map, int layers) : map_(map), slots_(static_cast<std::size_t>(std::max(layers, 1))) {}

PagePool::Frame PagePool::update(const std::vector<std::uint32_t>& requested, const glm::vec3& eye) {
  ++frame_;
  // Coarser first, as (−level, page): they serve wherever finer ones go without.
  std::vector<std::pair<int, std::uint32_t>> by_level;
  for (std::uint32_t id : requested) by_level.emplace_back(-map_.page(id).level, id);
  std::sort(by_level.begin(), by_level.end());
  by_level.erase(std::unique(by_level.begin(), by_level.end()), by_level.end());
  Frame frame;
  frame.requested = static_cast<int>(by_level.size());
  std::vector<std::uint32_t> missing;
  for (const auto& [level, id] : by_level) {
    const auto found = held_.find(id);
    if (found == held_.end()) {
      missing.push_back(id);
      continue;
    }
    Slot& slot = slots_[static_cast<std::size_t>(found->second)];
    slot.last_asked = frame_;
    if (slot.drawn) {
      ++frame.cached;
    } else {
      frame.to_draw.emplace_back(map_.page(id), found->second);
      slot.drawn = true;
      slot.drawn_from = eye;
    }
  }
  // The layers this frame did not ask for, free ones first, then the least recently asked for.
  std::vector<int> spare;
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    if (slots_[i].last_asked < frame_ || !slots_[i].page) spare.push_back(static_cast<int>(i));
  }
  std::sort(spare.begin(), spare.end(), [this](int a, int b) {
    const Slot& sa = slots_[static_cast<std::size_t>(a)];
    const Slot& sb = slots_[static_cast<std::size_t>(b)];
    if (sa.page.has_value() != sb.page.has_value()) return !sa.page.has_value();
    return sa.last_asked < sb.last_asked;
  });
  std::size_t next = 0;
  for (std::uint32_t id : missing) {
    if (next == spare.size()) {
      ++frame.dropped;
      continue;
    }
    const int layer = spare[next++];
    Slot& slot = slots_[static_cast<std::size_t>(layer)];
    if (slot.page) held_.erase(*slot.page);
    slot = {id, frame_, true, eye};
    held_[id] = layer;
    frame.to_draw.emplace_back(map_.page(id), layer);
  }
  return frame;
}

void PagePool::invalidate(const std::function<bool(const Page&, const glm::vec3&)>& stale) {
  for (Slot& slot : slots_) {
    if (slot.page && stale(map_.page(*slot.page), slot.drawn_from)) slot.drawn = false;
  }
}

void PagePool::clear() {
  std::fill(slots_.begin(), slots_.end(), Slot{});
  held_.clear();
}

std::optional<int> PagePool::layer(std::uint32_t id) const {
  const auto found = held_.find(id);
  if (found == held_.end()) return std::nullopt;
  return found->second;
}

}  // namespace shadow
