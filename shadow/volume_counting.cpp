#include "shadow/volume_counting.hpp"

#include "shadow/convex_body.hpp"
#include "shadow/focus_body.hpp"

#include <algorithm>

namespace shadow {

std::vector<Plane> near_plane_light_hull(const Camera& camera, float aspect, const Light& light) {
  // A slab from just before the near plane to just behind it, a little wider than the view.
  Camera slab = camera;
  slab.near = 0.5f * camera.near;
  slab.far = 2.0f * camera.near;
  slab.fov_y_deg = std::min(camera.fov_y_deg * 1.05f, 179.0f);
  const ConvexBody near_plane = ConvexBody::from_corners(frustum_corners(slab.projection(aspect * 1.05f) * slab.view()));
  return hull_with_light(near_plane, light);
}

// A box wholly outside one plane is quickly told apart; the rest are clipped, for boxes beside the
// body but outside none of its planes (a ground that reaches past the body on every side).
bool meets(const std::vector<Plane>& planes, const Box& box) {
  for (const Plane& plane : planes) {
    bool all_outside = true;
    for (int i = 0; i < 8 && all_outside; ++i) all_outside = plane.distance(box.corner(i)) > 0.0f;
    if (all_outside) return false;
  }
  ConvexBody body = ConvexBody::from_box(box);
  body.clip(planes);
  return !body.empty();
}

}  // namespace shadow
