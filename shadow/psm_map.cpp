#include "shadow/psm_map.hpp"

#include "shadow/focus_body.hpp"
#include "shadow/light_projection.hpp"
#include "shadow/post_perspective.hpp"
#include "shadow/uniform_map.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace shadow {
namespace {

// Attempts at moving the virtual camera back, each twice as far as the last, from 1/8 of the
// casters' depth range to 2^(max_shift_steps - 5) times it, where the map is all but uniform.
constexpr int max_shift_steps = 14;

std::string describe(const PostPerspectiveSpace& space, const Light& light) {
  const PostPerspectiveLight kind = post_perspective_light(space.matrix, light);
  std::ostringstream s;
  s << "psm: " << (kind == PostPerspectiveLight::point ? "point" : kind == PostPerspectiveLight::inverted ? "inverted" : "directional")
    << " light, camera moved back " << std::fixed << std::setprecision(1) << space.shift << " m";
  return s.str();
}

}  // namespace

ShadowSetup perspective_shadow_map(const ShadowInputs& in) {
  const Light& light = in.light;
  const float aspect = in.aspect;
  Camera pushed = in.camera;
  pushed.near = std::clamp(in.nearest_visible, in.camera.near, 0.5f * in.camera.far);
  // The bodies of the camera with its near plane pushed; the camera's own where it is not.
  const FocusBodies bodies = pushed.near == in.camera.near ? in.bodies : focus_bodies(pushed.projection(aspect) * pushed.view(), light, in.scene);
  // Receivers all around a point light need the uniform cube: one warped map spreads its texels
  // too thin over them (a case of Stamminger and Drettakis 2002, Sect. 3.3: a near point light).
  ShadowSetup uniform = focused_uniform_map(in);
  if (bodies.receivers.empty() || uniform.selection == ViewSelection::cube_faces) return uniform;

  const PostPerspectiveSpace first = post_perspective_space(pushed, aspect, bodies.casters, pushed.near);
  const float depth_range = first.far - first.near;
  for (int step = 0; step < max_shift_steps; ++step) {
    const PostPerspectiveSpace space =
        step == 0 ? first
                  : post_perspective_space(pushed, aspect, bodies.casters, pushed.near,
                                           depth_range * std::exp2(static_cast<float>(step - 4)));
    const FocusBodies warped{bodies.receivers.transformed(space.matrix), bodies.casters.transformed(space.matrix)};
    // The camera looks down +z in post-perspective space.
    const std::optional<ShadowView> light_view = fit_light_view(space.matrix * homogeneous(light), warped, {0, 0, 1});
    if (!light_view) continue;
    const ShadowView view{light_view->view * space.matrix, light_view->projection};
    if (finite(view.view_projection())) return {{view}, ViewSelection::single, describe(space, light)};
  }
  return uniform;
}

}  // namespace shadow
