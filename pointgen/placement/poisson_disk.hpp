#pragma once
#include "pointgen/random.hpp"

#include <vector>

namespace pointgen {

// Points in the rectangle [min, max] no two closer than `radius`, filling it: Bridson's (2007)
// growth from active points with `attempts` candidates each and a background grid for the distance
// test, run tile by tile so that it scales. The grid's tiles are filled in four phases by the
// parity of their column and row; tiles of one phase are a tile apart, so they never see each
// other's points and run on `threads` threads at once. Each tile draws from a seed of its own
// (derived from one draw of `rng`), so the points are the same for any number of threads.
// With 12 attempts it places about 0.58 points per radius² of area.
std::vector<glm::vec2> poisson_disk(const glm::vec2& min, const glm::vec2& max, float radius, Random& rng,
                                    int attempts = 12, int threads = 0 /* 0: one per core */);

}  // namespace pointgen
