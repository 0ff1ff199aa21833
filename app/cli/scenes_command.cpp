#include "app/cli/scenes_command.hpp"

#include "app/resources.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <set>
#include <string>

namespace ecoview {
namespace {

std::string counted(std::size_t count, const std::string& thing) {
  return std::to_string(count) + " " + thing + (count == 1 ? "" : "s");
}

// "3 lights, 8 objects: A courtyard with walls, …" from the shipped scene file: its lights, its
// objects, the plants its ecosystems place, and its comment. Read, not loaded: an ecosystem
// takes seconds to build.
std::string scene_summary(const std::string& name) {
  const nlohmann::json scene = nlohmann::json::parse(*resources::find("data/scenes/" + name + ".json"), nullptr, false);
  if (!scene.is_object()) return "";
  const nlohmann::json& objects = scene.value("objects", nlohmann::json::array());
  std::size_t plants = 0;
  for (const nlohmann::json& object : objects) {
    for (const nlohmann::json& species : object.value("plants", nlohmann::json::array())) plants += species.value("count", 0u);
  }
  std::string summary = counted(scene.value("lights", nlohmann::json::array()).size(), "light") + ", " +
                        counted(objects.size(), "object");
  if (plants > 0) summary += ", " + counted(plants, "plant");
  if (const std::string comment = scene.value("comment", ""); !comment.empty()) summary += ": " + comment;
  return summary;
}

}  // namespace

CLI::App* add_scenes_command(CLI::App& app) {
  return app.add_subcommand("scenes", "List the shipped scenes (--scene NAME) and camera paths (--path NAME)");
}

int run_scenes() {
  const std::vector<std::string> scenes = resources::names_in("data/scenes", ".json");
  const std::vector<std::string> paths = resources::names_in("data/paths", ".json");
  std::set<std::string> names(scenes.begin(), scenes.end());
  names.insert(paths.begin(), paths.end());
  std::size_t width = 0;
  for (const std::string& name : names) width = std::max(width, name.size());
  std::cout << "Shipped scenes (--scene NAME) and camera paths (--path NAME), by name:\n";
  for (const std::string& name : names) {
    const bool scene = std::binary_search(scenes.begin(), scenes.end(), name);
    const bool path = std::binary_search(paths.begin(), paths.end(), name);
    std::cout << "  " << name << std::string(width - name.size(), ' ')
              << (scene && path ? "  scene and path  " : scene ? "  scene           " : "  path            ")
              << (scene ? scene_summary(name) : "") << "\n";
  }
  return 0;
}

}  // namespace ecoview
