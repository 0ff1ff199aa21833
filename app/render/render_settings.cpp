#include "app/render/render_settings.hpp"

#include "shadow/techniques.hpp"
#include "shadow/virtual_map.hpp"

#include <cstdint>

namespace ecoview {

std::string shadow_depth_name(ShadowDepth depth) {
  switch (depth) {
    case ShadowDepth::fixed16: return "16";
    case ShadowDepth::fixed24: return "24";
    case ShadowDepth::float32: return "32f";
  }
  return "";
}

int map_texels(const RenderSettings& settings) {
  return shadow::technique(settings.method).lookup == shadow::Lookup::pages ? shadow::VirtualMap{}.tile_texels() : settings.shadow_size;
}

int page_pool_layers(const RenderSettings& settings) {
  std::int64_t texel_bytes = settings.shadow_depth == ShadowDepth::fixed16 ? 2 : 4;  // 24 bits are stored in 32
  if (shadow::technique(settings.method).silhouette_map) texel_bytes += 4;  // a silhouette point, RG16F
  const std::int64_t side = shadow::VirtualMap{}.layer_texels();
  return static_cast<int>((static_cast<std::int64_t>(settings.page_pool_mib) << 20) / (side * side * texel_bytes));
}

RenderSettings for_scene(RenderSettings settings, const Scene& scene) {
  settings.points = settings.points && scene.has_point_meshes();
  return settings;
}

}  // namespace ecoview
