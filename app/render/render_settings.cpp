#include "app/render/render_settings.hpp"

namespace ecoview {

std::string shadow_depth_name(ShadowDepth depth) {
  switch (depth) {
    case ShadowDepth::fixed16: return "16";
    case ShadowDepth::fixed24: return "24";
    case ShadowDepth::float32: return "32f";
  }
  return "";
}

RenderSettings for_scene(RenderSettings settings, const Scene& scene) {
  settings.points = settings.points && scene.has_point_meshes();
  return settings;
}

}  // namespace ecoview
