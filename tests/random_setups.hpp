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

}  // namespace shadow
