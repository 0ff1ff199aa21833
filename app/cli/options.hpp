#pragma once
#include "app/scene/scene.hpp"

#include <glm/glm.hpp>

#include <string>

// Validation of command-line values shared by the subcommands; each throws InputError naming
// the option.
namespace ecoview {

glm::ivec2 parse_size(const std::string& text);  // "WxH"

struct FrameRange {
  int begin = 0;
  int end = 1;  // one past the last frame
};
FrameRange parse_frames(const std::string& text);  // "A:B", frames A … B-1

int check_shadow_size(int size);
double check_fps(double fps);

// The scene named by --scene (a file or a shipped scene; the default scene when empty), refused
// when it would need more than `memory_budget_gib` (--memory-budget).
Scene load_scene_option(const std::string& scene, double memory_budget_gib);
// The light selected by --light.
const shadow::Light& select_light(const Scene& scene, int index);

}  // namespace ecoview
