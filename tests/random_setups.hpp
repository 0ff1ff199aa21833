#pragma once
// Random cameras and lights over a 100 x 20 x 100 m scene box, for the shadow-map tests, and the
// bits of geometry those tests share.
#include "pointgen/random.hpp"
#include "shadow/box.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"
#include "shadow/shadow_setup.hpp"

namespace shadow {

glm::vec3 random_unit(pointgen::Random& rng);
Box scene_box();
Camera random_camera(pointgen::Random& rng);
Light random_light(pointgen::Random& rng, LightType type);
// The PSM paper's best case (Stamminger and Drettakis 2002, Sect. 3.3): a camera 2 m up looking far along the ground,
// for a light across the view.
Camera deep_view_camera();
Camera camera_looking(const glm::vec3& position, const glm::vec3& target, float near, float far);

// Where a projective matrix takes p, divided by w.
glm::vec3 ndc(const glm::mat4& m, const glm::vec3& p);
// World area of the ground (the xz plane) per unit of a map's ndc area at p: the inverse
// determinant of the map's ndc xy against the ground's x and z, by central differences over half a
// metre (exact for an affine map, within 0.3 % for the projective ones of these tests, which vary
// over 7 m or more, and long enough to stay clear of rounding in nearly affine warps).
float ground_texel_area(const glm::mat4& m, const glm::vec3& p);

}  // namespace shadow
