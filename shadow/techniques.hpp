#pragma once
#include "shadow/light.hpp"
#include "shadow/shadow_inputs.hpp"
#include "shadow/shadow_setup.hpp"

#include <string>
#include <string_view>
#include <vector>

// Every shadow technique, registered in one table: what the command line, the viewer, the
// benchmarks, `auto` and the renderer know of a method they read here. Adding a method is a setup
// function and one row of the table; a mask is a MaskTechnique on the GL side, registered in
// app/render/mask_technique.cpp.
namespace shadow {

enum class Method { none, uniform, psm, lispsm, cascades, dpsm, ipsm, silhouette, psm_silhouette, adaptive, adaptive_silhouette, volumes, hybrid, reference, automatic };

// What a technique hands the frame's lighting.
enum class Lookup {
  none,  // no shadows
  map,   // a shadow map, one layer per view of its ShadowSetup: polygons and point splats cast
  // a virtual map of each view of its ShadowSetup, paged (shadow/virtual_map.hpp): drawn after the
  // frame's surfaces, only the pages they ask for; polygons and point splats cast
  pages,
  mask,  // a per-pixel mask of the frame's lit surfaces, made after them (with a map's help where
         // the technique has a setup): polygons cast
};

// What a technique takes from the frame before it.
enum class LastFrame {
  nothing,
  nearest_depth,  // the nearest surface's depth (ShadowInputs::nearest_visible)
  surface,        // the surface the frame showed, with its camera (and the nearest depth)
};

// Light types, as a set.
struct Lights {
  bool directional = false, point = false, spot = false;
  bool has(LightType type) const {
    return type == LightType::directional ? directional : type == LightType::point ? point : spot;
  }
  bool all() const { return directional && point && spot; }
  bool operator==(const Lights&) const = default;
};

struct Technique {
  Method method;
  std::string name;  // as --method takes it
  std::string help;  // what it is, in a phrase
  Lookup lookup;
  Lights warps;  // the lights it handles itself; its setup hands the others to the focused uniform map
  LastFrame last_frame;
  // Whether the CPU sampler may skip point casters whose shadows fall on nothing the last frame
  // showed (pointgen::ReceiverMask).
  bool culls_casters;
  // The map's views for a frame (for `hybrid`, the map that decides where its volumes count); none
  // for `none`, `volumes`, `reference` and `auto` (which predicts each candidate's aliasing on the
  // last frame's surface, on the GPU).
  ShadowSetup (*setup)(const ShadowInputs&) = nullptr;
  // Whether a silhouette map goes with the map (Sen, Cammarano and Hanrahan 2003): the lookup
  // rebuilds the polygon casters' shadow edges from it, instead of filtering the depths; a mask's
  // map (`hybrid`) finds from it where a shadow thinner than a texel may fall.
  bool silhouette_map = false;

  // Whether a shadow map is drawn for the frame: looked up, or helping to make the mask.
  bool has_map() const { return lookup == Lookup::map || lookup == Lookup::pages || (lookup == Lookup::mask && setup != nullptr); }
};

// Every technique, in the order --help and the viewer list them.
const std::vector<Technique>& techniques();
const Technique& technique(Method method);
// The technique named `name`; nullptr where there is none.
const Technique* find_technique(std::string_view name);
// The maps whose own setup handles a light (looked up, with a setup, warps.has(light)).
std::vector<Method> map_techniques(LightType light);
// The maps `auto` chooses among for a light: those, filtered (a silhouette map changes the edges,
// not the aliasing auto predicts).
std::vector<Method> auto_candidates(LightType light);

}  // namespace shadow
