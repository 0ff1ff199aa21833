#pragma once
#include "pointgen/landscape/landscape_spec.hpp"

namespace pointgen {

// Species `species` of layer `layer`'s grove field at (x, z), in [0, 1]: its own noise, so that
// species of a layer grow in groves of their own and the layer is bare where none reaches its
// threshold.
float grove_noise(const LandscapeSpec& spec, int layer, int species, glm::vec2 p);

// Whether the species grows at p, whose ground stands at `height`: its altitude range, its grove
// threshold and its steepest slope, cheapest first.
bool grows_at(const LandscapeSpec& spec, const LandscapeTerrain& terrain, int layer, int species, glm::vec2 p, float height);

}  // namespace pointgen
