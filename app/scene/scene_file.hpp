#pragma once
#include "app/scene/scene.hpp"
#include "pointgen/mesh_file.hpp"

#include <string>

namespace ecoview {

// Where a scene or path comes from: a file on disk or a resource shipped in the binary. Files it
// names (meshes) are read relative to its folder, from the same place.
struct InputSource {
  std::string name;   // for messages: the path as given, or "data/scenes/NAME.json"
  std::string text;
  pointgen::ReadFile read_relative;  // reads a path relative to the source's folder
};

// `name_or_file` is a path to a file or the name of a file shipped under data/<folder>/
// (e.g. "courtyard" for data/scenes/courtyard.json). Throws InputError when it is neither.
InputSource open_input(const std::string& name_or_file, const std::string& folder);

struct LoadLimits {
  // A scene that would need more memory than this is refused before it is built.
  double memory_budget_bytes = 4.0 * 1024 * 1024 * 1024;
  // The most memory a landscape's plants take at once (--plant-pool): fewer where its cells within
  // reach of any eye hold fewer.
  double plant_pool_bytes = 256.0 * 1024 * 1024;
};

// Parses the scene JSON (format in docs/scenes.md), loads the meshes it names and grows
// the procedural objects. Throws InputError naming the file and field.
Scene load_scene(const InputSource& source, const LoadLimits& limits = {});

// The scene used when no --scene is given.
constexpr const char* default_scene_name = "ecosystem";

}  // namespace ecoview
