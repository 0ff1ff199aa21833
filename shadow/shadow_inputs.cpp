#include "shadow/shadow_inputs.hpp"

namespace shadow {

ShadowInputs::ShadowInputs(const Camera& camera, float aspect, const Light& light, const Box& scene, int map_size,
                           float nearest_visible)
    : camera(camera),
      aspect(aspect),
      light(light),
      scene(scene),
      map_size(map_size),
      nearest_visible(nearest_visible),
      bodies(focus_bodies(view_projection(), light, scene)),
      bodies_or_scene(or_scene(bodies, light, scene)) {}

}  // namespace shadow
