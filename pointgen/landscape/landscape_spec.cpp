#include "pointgen/landscape/landscape_spec.hpp"

#include <stdexcept>

namespace pointgen {
namespace {

void require(bool valid, const std::string& field, const std::string& why) {
  if (!valid) throw std::invalid_argument(field + ": " + why);
}

void check_species(const LandscapeSpecies& s, const std::string& at) {
  require(s.weight >= 0.0f, at + ".weight", "must be at least 0");
  require(s.altitude.x <= s.altitude.y, at + ".altitude", "the lowest must not be above the highest");
  require(s.slope_max_deg >= 0.0f && s.slope_max_deg <= 90.0f, at + ".slope_max_deg", "must be from 0 to 90");
  require(s.grove >= 0.0f && s.grove <= 1.0f, at + ".grove", "must be from 0 to 1");
  require(s.grove_size > 0.0f, at + ".grove_size", "must be above 0");
  require(s.scale.x > 0.0f && s.scale.x <= s.scale.y, at + ".scale", "must be above 0, the smaller first");
  require(s.tint_spread >= 0.0f && s.tint_spread <= 1.0f, at + ".tint_spread", "must be from 0 to 1");
  require(s.surface >= 0.0f, at + ".surface", "must be at least 0");
}

void check_layer(const LandscapeLayer& layer, const std::string& at) {
  require(layer.cell_size > 0.0f, at + ".cell_size", "must be above 0");
  require(layer.density >= 0.0f, at + ".density", "must be at least 0");
  require(layer.density * layer.cell_size * layer.cell_size <= LandscapeSpec::max_sites_per_cell, at + ".density",
          "times the cell's area must be at most " + std::to_string(static_cast<int>(LandscapeSpec::max_sites_per_cell)) +
              " plants a cell");
  for (std::size_t s = 0; s < layer.species.size(); ++s) check_species(layer.species[s], at + ".species[" + std::to_string(s) + "]");
  require(layer.species.empty() || layer.total_weight() > 0.0f, at + ".species", "some weight must be above 0");
}

}  // namespace

float LandscapeLayer::total_weight() const {
  float total = 0.0f;
  for (const LandscapeSpecies& s : species) total += s.weight;
  return total;
}

void LandscapeSpec::check() const {
  require(size.x > 0.0f && size.y > 0.0f && size.x <= max_size && size.y <= max_size, "size",
          "must be above 0 and at most " + std::to_string(static_cast<int>(max_size)) + " m");
  require(terrain.feature > 0.0f && terrain.valley_width > 0.0f && terrain.valley_wavelength > 0.0f, "terrain",
          "feature, valley_width and valley_wavelength must be above 0");
  require(terrain.octaves >= 1 && terrain.octaves <= 12, "terrain.octaves", "must be from 1 to 12");
  for (std::size_t l = 0; l < layers.size(); ++l) check_layer(layers[l], "layers[" + std::to_string(l) + "]");
}

}  // namespace pointgen
