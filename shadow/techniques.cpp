#include "shadow/techniques.hpp"

#include "shadow/cascaded_map.hpp"
#include "shadow/lispsm_map.hpp"
#include "shadow/paraboloid_map.hpp"
#include "shadow/psm_map.hpp"
#include "shadow/uniform_map.hpp"

namespace shadow {
namespace {

constexpr Lights every_light{true, true, true};
constexpr Lights directional_lights{true, false, false};
constexpr Lights point_and_spot_lights{false, true, true};

ShadowSetup four_cascades(const ShadowInputs& in) { return cascaded_map(in); }

}  // namespace

const std::vector<Technique>& techniques() {
  static const std::vector<Technique> table = {
      {Method::uniform, "uniform", "the plain shadow map fitted to the view: even texels, blocky near the camera",
       Lookup::map, every_light, LastFrame::nothing, true, focused_uniform_map},
      {Method::psm, "psm", "perspective shadow map (Stamminger and Drettakis 2002): more texels near the camera",
       Lookup::map, every_light, LastFrame::nearest_depth, true, perspective_shadow_map},
      {Method::lispsm, "lispsm", "light space perspective shadow map (Wimmer et al. 2004): a milder warp",
       Lookup::map, directional_lights, LastFrame::nothing, true, light_space_perspective_map},
      {Method::cascades, "cascades", "four maps over slices of distance, practical splits, texel snapping",
       Lookup::map, directional_lights, LastFrame::nothing, true, four_cascades},
      {Method::dpsm, "dpsm", "dual paraboloid map around a point or spot light",
       Lookup::map, point_and_spot_lights, LastFrame::nothing, true, dual_paraboloid_map},
      {Method::ipsm, "ipsm", "improved paraboloid map, turned and cut to the receivers (Vanek et al. 2011)",
       Lookup::map, point_and_spot_lights, LastFrame::nothing, true, improved_paraboloid_map},
      {Method::silhouette, "silhouette", "the uniform map and its silhouette map, for sharp edges (Sen et al. 2003)",
       Lookup::map, every_light, LastFrame::nothing, true, focused_uniform_map, true},
      {Method::psm_silhouette, "psm+silhouette", "the perspective shadow map and its silhouette map",
       Lookup::map, every_light, LastFrame::nearest_depth, true, perspective_shadow_map, true},
      {Method::adaptive, "adaptive", "pages of a huge virtual map drawn where pixels need them (Fernando et al. 2001)",
       Lookup::pages, every_light, LastFrame::nothing, false, lit_scene_map},
      {Method::adaptive_silhouette, "adaptive+silhouette", "the adaptive map with a silhouette map in each page",
       Lookup::pages, every_light, LastFrame::nothing, false, lit_scene_map, true},
      {Method::volumes, "volumes", "exact shadows of polygons by stencil shadow volumes",
       Lookup::mask, every_light, LastFrame::nothing, false},
      {Method::hybrid, "hybrid", "the uniform map, with shadow volumes only near its edges (Chan and Durand 2004)",
       Lookup::mask, every_light, LastFrame::nothing, false, focused_uniform_map, true},
      {Method::reference, "reference", "exact shadows: rays to the light against every triangle, with Embree",
       Lookup::mask, every_light, LastFrame::nothing, false},
      {Method::automatic, "auto", "each frame, the map method predicted to alias least",
       Lookup::map, every_light, LastFrame::surface, true},
      {Method::none, "none", "no shadows",
       Lookup::none, every_light, LastFrame::nothing, false},
  };
  return table;
}

const Technique& technique(Method method) {
  for (const Technique& t : techniques()) {
    if (t.method == method) return t;
  }
  return techniques().back();  // unreachable: every method has a row
}

const Technique* find_technique(std::string_view name) {
  for (const Technique& t : techniques()) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

std::vector<Method> map_techniques(LightType light) {
  std::vector<Method> maps;
  for (const Technique& t : techniques()) {
    if (t.lookup == Lookup::map && t.setup && t.warps.has(light)) maps.push_back(t.method);
  }
  return maps;
}

std::vector<Method> auto_candidates(LightType light) {
  std::vector<Method> candidates = map_techniques(light);
  std::erase_if(candidates, [](Method m) { return technique(m).silhouette_map; });
  return candidates;
}

}  // namespace shadow
