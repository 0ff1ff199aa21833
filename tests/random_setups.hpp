#pragma once
// Random cameras and lights over a 100 x 20 x 100 m scene box, for the shadow-map tests.
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
// The PSM paper's best case (seed 000, Sect. 3.3): a camera 2 m up looking far along the ground,
// for a light across the view.
Camera deep_view_camera();

}  // namespace shadow
