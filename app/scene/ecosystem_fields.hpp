#pragma once
#include "app/scene/json_input.hpp"
#include "pointgen/placement/ecosystem.hpp"

// Readers for the procedural parts of a scene file: plant species and ecosystems.
namespace ecoview {

// A species: a catalogue name ("oak"), or an object of PlantSpecies fields, optionally "like" a
// catalogue species it starts from. `defined` holds species the scene file defined by name.
pointgen::PlantSpecies read_species(const JsonField& field, const std::vector<pointgen::PlantSpecies>& defined);

// {"seed", "center", "size", "terrain": {...}, "species": [...], "plants": [{"species", "count", "variants"}]};
// its seed is derived from the scene's and its own.
pointgen::EcosystemSpec read_ecosystem(const JsonField& field, std::uint64_t scene_seed);

}  // namespace ecoview
