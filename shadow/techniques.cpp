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
      {Method::uniform, "uniform", "focused uniform shadow map", Lookup::map, every_light, LastFrame::nothing, true,
       focused_uniform_map},
      {Method::psm, "psm", "perspective shadow map, built in the camera's post-perspective space", Lookup::map, every_light,
       LastFrame::nearest_depth, true, perspective_shadow_map},
      {Method::lispsm, "lispsm", "light space perspective shadow map", Lookup::map, directional_lights, LastFrame::nothing,
       true, light_space_perspective_map},
      {Method::cascades, "cascades", "4 cascades, practical splits, texel snapping", Lookup::map, directional_lights,
       LastFrame::nothing, true, four_cascades},
      {Method::dpsm, "dpsm", "dual paraboloid map", Lookup::map, point_and_spot_lights, LastFrame::nothing, true,
       dual_paraboloid_map},
      {Method::ipsm, "ipsm", "improved paraboloid map, turned and cut to the receivers", Lookup::map, point_and_spot_lights,
       LastFrame::nothing, true, improved_paraboloid_map},
      {Method::silhouette, "silhouette",
       "the focused uniform map and its silhouette map: per texel a point of the polygon casters' silhouette edges, "
       "from which the lookup rebuilds sharp shadow edges (Sen, Cammarano and Hanrahan 2003); point splats cast through the depths alone",
       Lookup::map, every_light, LastFrame::nothing, true, focused_uniform_map, true},
      {Method::psm_silhouette, "psm+silhouette", "the perspective shadow map and its silhouette map, looked up as silhouette's",
       Lookup::map, every_light, LastFrame::nearest_depth, true, perspective_shadow_map, true},
      {Method::adaptive, "adaptive",
       "adaptive shadow map (Fernando et al. 2001) as a virtual map paged like production engines page theirs: the "
       "uniform map of the lit scene (the same views whatever the camera) at 524,288 texels a side in 12 levels, the fine ones "
       "addressed in windows around the camera as clipmaps; each pixel asks for the page whose texels are "
       "a pixel wide or finer there, and only the pages asked for are drawn, after the frame's surfaces, and kept "
       "across frames in a pool of layers (--page-pool)",
       Lookup::pages, every_light, LastFrame::nothing, false, lit_scene_map},
      {Method::adaptive_silhouette, "adaptive+silhouette",
       "the adaptive map with a silhouette map in each page, looked up as silhouette's: sharper edges for a "
       "geometry-shader pass over the polygon casters that reach each tile of pages drawn (on llvmpipe 1.1-2 times adaptive's frame)",
       Lookup::pages, every_light, LastFrame::nothing, false, lit_scene_map, true},
      {Method::volumes, "volumes", "exact shadows of polygons by stencil shadow volumes from silhouette edges, counted z-pass where the camera stands in no volume and z-fail elsewhere; point splats cast none, and alpha masks do not cut the volumes",
       Lookup::mask, every_light, LastFrame::nothing, false},
      {Method::hybrid, "hybrid",
       "the focused uniform map, and shadow volumes counted only where its test is neither lit nor shadowed, near "
       "the edges of its shadows (Chan and Durand 2004), or where a caster's silhouette edge crosses the surface's texel "
       "(shadows thinner than a texel): the volumes' edges at a fraction of their fill; point splats cast through the map",
       Lookup::mask, every_light, LastFrame::nothing, false, focused_uniform_map, true},
      {Method::reference, "reference", "exact: rays to the light against every triangle, plants as meshes, with Embree",
       Lookup::mask, every_light, LastFrame::nothing, false},
      {Method::automatic, "auto",
       "each frame the map whose median aliasing factor, predicted from its matrices on the last frame's surface, is least",
       Lookup::map, every_light, LastFrame::surface, true},
      {Method::none, "none", "no shadows", Lookup::none, every_light, LastFrame::nothing, false},
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
