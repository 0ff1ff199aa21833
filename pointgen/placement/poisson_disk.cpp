#include "pointgen/placement/poisson_disk.hpp"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace pointgen {

std::vector<glm::vec2> poisson_disk(const glm::vec2& min, const glm::vec2& max, float radius, Random& rng,
                                    int attempts) {
  const float cell = radius / std::sqrt(2.0f);  // a cell holds at most one point
  const glm::ivec2 cells = glm::max(glm::ivec2(1), glm::ivec2(glm::ceil((max - min) / cell)));
  std::vector<std::int32_t> grid(static_cast<std::size_t>(cells.x) * static_cast<std::size_t>(cells.y), -1);
  std::vector<glm::vec2> points;
  std::vector<std::size_t> active;
  auto cell_of = [&](const glm::vec2& p) { return glm::min(glm::ivec2((p - min) / cell), cells - 1); };
  auto add = [&](const glm::vec2& p) {
    const glm::ivec2 c = cell_of(p);
    grid[static_cast<std::size_t>(c.y) * static_cast<std::size_t>(cells.x) + static_cast<std::size_t>(c.x)] =
        static_cast<std::int32_t>(points.size());
    active.push_back(points.size());
    points.push_back(p);
  };
  auto far_enough = [&](const glm::vec2& p) {
    const glm::ivec2 c = cell_of(p);
    for (int y = std::max(0, c.y - 2); y <= std::min(cells.y - 1, c.y + 2); ++y) {
      for (int x = std::max(0, c.x - 2); x <= std::min(cells.x - 1, c.x + 2); ++x) {
        const std::int32_t q = grid[static_cast<std::size_t>(y) * static_cast<std::size_t>(cells.x) + static_cast<std::size_t>(x)];
        if (q >= 0) {
          const glm::vec2 d = points[static_cast<std::size_t>(q)] - p;
          if (glm::dot(d, d) < radius * radius) return false;
        }
      }
    }
    return true;
  };

  add(glm::vec2(rng.uniform(min.x, max.x), rng.uniform(min.y, max.y)));
  while (!active.empty()) {
    const std::size_t pick = rng.below(static_cast<std::uint32_t>(active.size()));
    const glm::vec2 center = points[active[pick]];
    bool placed = false;
    for (int k = 0; k < attempts && !placed; ++k) {
      const float angle = rng.uniform(0.0f, glm::two_pi<float>());
      const float distance = radius * std::sqrt(rng.uniform(1.0f, 4.0f));  // uniform over the annulus r..2r
      const glm::vec2 p = center + distance * glm::vec2(std::cos(angle), std::sin(angle));
      if (p.x < min.x || p.y < min.y || p.x >= max.x || p.y >= max.y || !far_enough(p)) continue;
      add(p);
      placed = true;
    }
    if (!placed) {
      active[pick] = active.back();
      active.pop_back();
    }
  }
  return points;
}

}  // namespace pointgen
