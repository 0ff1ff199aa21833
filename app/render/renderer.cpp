#include "app/render/renderer.hpp"

#include "app/errors.hpp"
#include "shadow/uniform_map.hpp"

namespace ecoview {

ShadowMethod parse_shadow_method(const std::string& name) {
  if (name == "uniform") return ShadowMethod::uniform;
  if (name == "none") return ShadowMethod::none;
  throw InputError("--method: '" + name + "' is not available in this build (available: uniform, none)");
}

Renderer::Renderer(const Scene& scene, const RenderSettings& settings)
    : scene_(scene),
      settings_(settings),
      scene_bounds_(scene.bounds()),
      gpu_scene_(scene),
      shadow_pass_(settings.shadow_size),
      frame_pass_(settings.width, settings.height) {}

void Renderer::render(const shadow::Camera& camera, const shadow::Light& light, double t) {
  for (const Animation& animation : scene_.animations) {
    const std::vector<pointgen::InstanceTable> tables = animation.set.pose(t, animation.first_mesh);
    for (std::size_t i = 0; i < tables.size(); ++i) gpu_scene_.update(animation.first_group + i, tables[i]);
  }
  std::optional<FramePass::ShadowLookup> lookup;
  if (settings_.method == ShadowMethod::uniform) {
    const float aspect = static_cast<float>(settings_.width) / static_cast<float>(settings_.height);
    setup_ = shadow::focused_uniform_map(camera, aspect, light, scene_bounds_, settings_.shadow_size);
    shadow_pass_.render(gpu_scene_, setup_);
    lookup.emplace(FramePass::ShadowLookup{shadow_pass_.depth_texture(), setup_, shadow_pass_.size()});
  }
  frame_pass_.render(gpu_scene_, camera, light, lookup);
}

}  // namespace ecoview
