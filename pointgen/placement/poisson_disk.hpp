#pragma once
#include "pointgen/random.hpp"

#include <vector>

namespace pointgen {

// Points in the rectangle [min, max] no two closer than `radius`, filling it (Bridson 2007: grow
// from active points, `attempts` candidates each, a background grid for the distance test).
std::vector<glm::vec2> poisson_disk(const glm::vec2& min, const glm::vec2& max, float radius, Random& rng,
                                    int attempts = 20);

}  // namespace pointgen
