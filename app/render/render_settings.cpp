#include "app/render/render_settings.hpp"

namespace ecoview {

RenderSettings for_scene(RenderSettings settings, const Scene& scene) {
  settings.points = settings.points && scene.has_point_meshes();
  return settings;
}

}  // namespace ecoview
