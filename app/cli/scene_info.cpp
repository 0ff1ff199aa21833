#include "app/cli/scene_info.hpp"

#include <cstdio>
#include <fstream>
#include <string>

namespace ecoview {

double resident_mib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // the value is in kB
  }
  return 0.0;
}

std::string describe_scene(const Scene& scene, double load_seconds) {
  char textures[64] = "";
  if (const std::size_t bytes = scene.texture_bytes(); bytes > 0) {
    std::snprintf(textures, sizeof textures, ", %.3g MiB of textures", static_cast<double>(bytes) / (1024.0 * 1024.0));
  }
  char landscape[64] = "";
  if (scene.landscape_plants > 0.0) {
    std::snprintf(landscape, sizeof landscape, ", a landscape of about %.3g plants", scene.landscape_plants);
  }
  char text[512];
  std::snprintf(text, sizeof text, "scene: %s: %zu instances%s, %.3g triangles as polygons, %zu meshes%s; loaded in %.2f s, %.0f MiB resident",
                scene.name.c_str(), scene.instance_count(), landscape, static_cast<double>(scene.triangle_count()), scene.meshes.size(),
                textures, load_seconds, resident_mib());
  return text;
}

}  // namespace ecoview
