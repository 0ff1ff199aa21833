#pragma once
#include "app/scene/json_input.hpp"
#include "pointgen/placement/ecosystem.hpp"

#include <functional>

// Readers for the procedural parts of a scene file: plant species and ecosystems.
namespace ecoview {

// A species: a catalogue name ("oak"), or an object of PlantSpecies fields, optionally "like" a
// catalogue species it starts from. `defined` holds species the scene file defined by name.
pointgen::PlantSpecies read_species(const JsonField& field, const std::vector<pointgen::PlantSpecies>& defined);

// Loads the mesh file a field names (relative to the scene file); InputError on the field when it
// cannot.
using LoadMesh = std::function<pointgen::TriangleMesh(const JsonField& file)>;

// {"seed", "center", "size", "terrain": {...}, "species": [...], "plants": [...]}, each plant
// entry {"species", "count", "variants"} or, for the user's own species, {"file", "count",
// "layer": "trees" | "bushes" | "ground", "scale": [min, max]}; either with "tint", from 0 to 1,
// the most a plant's colour differs per channel (PlantRequest::tint; a species from a file is not
// tinted unless asked). Its seed is derived from the scene's and its own.
pointgen::EcosystemSpec read_ecosystem(const JsonField& field, std::uint64_t scene_seed, const LoadMesh& load_mesh);

}  // namespace ecoview
