#pragma once
#include "shadow/camera.hpp"
#include "shadow/convex_body.hpp"
#include "shadow/light.hpp"

// The camera's post-perspective space as the perspective shadow map uses it (Stamminger and Drettakis 2002, Sects. 3
// and 4.2), and what a light becomes there.
namespace shadow {

// World → post-perspective space (clip coordinates: divide by w) of a virtual camera: the camera
// moved back along its view axis by `shift`.
struct PostPerspectiveSpace {
  glm::mat4 matrix{1.0f};
  float shift = 0.0f;  // metres the camera was moved back
  float near = 0.0f;   // of the virtual camera
  float far = 0.0f;
};

// The virtual camera for `casters` (H): moved back by what H needs to lie at least `near` in
// front of it, plus `extra_shift`; its near plane at H's nearest point, its far plane at H's
// farthest. The further it is moved back, the closer the space comes to an affine copy of world
// space, and a shadow map in it to a uniform one.
PostPerspectiveSpace post_perspective_space(const Camera& camera, float aspect, const ConvexBody& casters, float near,
                                            float extra_shift = 0.0f);

// The homogeneous point a light shines from: (position, 1), or (-direction, 0) at infinity.
glm::vec4 homogeneous(const Light& light);

// Seed 000, Sect. 3 and Figs. 4–5: in post-perspective space a light is a point light (a
// directional light shining from in front of the viewer, a point light in front of the camera
// plane), an inverted point light whose rays converge on it (either behind the viewer), or a
// directional light (a directional light parallel to the image plane, a point light in the camera
// plane).
enum class PostPerspectiveLight { point, inverted, directional };

PostPerspectiveLight post_perspective_light(const glm::mat4& post_perspective, const Light& light);

}  // namespace shadow
