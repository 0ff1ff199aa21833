#pragma once
#include "shadow/box.hpp"
#include "shadow/camera.hpp"
#include "shadow/focus_body.hpp"
#include "shadow/light.hpp"

// What every shadow technique sets its maps up from, made once per frame: the focus bodies are
// clipped here, not again by each method and by the uniform map each falls back to.
namespace shadow {

struct ShadowInputs {
  Camera camera;
  float aspect = 1.0f;  // the frame's width / height
  Light light;
  Box scene;
  int map_size = 1;  // texels per side of one map
  // The depth of the nearest surface the camera saw last frame, with a margin (the PSM's near
  // plane, Stamminger and Drettakis 2002, Sect. 6); 0 when unknown.
  float nearest_visible = 0.0f;
  FocusBodies bodies;           // focus_bodies of the camera: empty where it sees no lit scene
  FocusBodies bodies_or_scene;  // or_scene(bodies): never empty, for maps that must cover something

  ShadowInputs(const Camera& camera, float aspect, const Light& light, const Box& scene, int map_size,
               float nearest_visible = 0.0f);

  glm::mat4 view_projection() const { return camera.projection(aspect) * camera.view(); }
};

}  // namespace shadow
