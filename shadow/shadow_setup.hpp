#pragma once
#include <glm/glm.hpp>

namespace shadow {

// What a renderer needs to draw one shadow map and look it up: world → light space → light clip
// space. Points that must be covered map into the clip cube [-1, 1]^3.
struct ShadowSetup {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};

  glm::mat4 view_projection() const { return projection * view; }
};

}  // namespace shadow
