#include "pointgen/sampling/receiver_mask.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <vector>

namespace pointgen {
namespace {

// A light looking straight down on the square [-50, 50]² of the ground: one metre is 64/100 of a
// tile, a tile about 1.6 m.
const glm::mat4 light_view = glm::ortho(-50.0f, 50.0f, -50.0f, 50.0f, 0.0f, 200.0f) *
                             glm::lookAt(glm::vec3(0.0f, 100.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));

glm::mat4 at(float x, float z) { return glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, z)); }

TEST(ReceiverMask, ACasterShadowsOnlyWhereReceiversLieBelowIt) {
  // Receivers: a patch of ground 4 m across around (20, -10).
  std::vector<glm::vec3> receivers;
  for (float x = 18.0f; x <= 22.0f; x += 0.5f) {
    for (float z = -12.0f; z <= -8.0f; z += 0.5f) receivers.emplace_back(x, 0.0f, z);
  }
  const ReceiverMask mask(light_view, receivers);
  const glm::vec3 center(0.0f, 5.0f, 0.0f), half(1.0f, 5.0f, 1.0f);  // a tree 10 m tall, 2 m wide
  EXPECT_TRUE(mask.may_shadow(center, half, at(20.0f, -10.0f)));
  EXPECT_TRUE(mask.may_shadow(center, half, at(23.0f, -10.0f))) << "overlapping the patch's edge";
  EXPECT_TRUE(mask.may_shadow(center, half, at(24.5f, -10.0f))) << "a tile from the patch: kept for filtering";
  EXPECT_FALSE(mask.may_shadow(center, half, at(-20.0f, 30.0f)));
  EXPECT_FALSE(mask.may_shadow(center, half, at(30.0f, -10.0f)));
  EXPECT_FALSE(mask.may_shadow(center, half, at(200.0f, 0.0f))) << "outside the view";
}

TEST(ReceiverMask, NoReceiversNoCasters) {
  const ReceiverMask mask(light_view, {});
  EXPECT_FALSE(mask.may_shadow(glm::vec3(0.0f), glm::vec3(1.0f), glm::mat4(1.0f)));
}

TEST(ReceiverMask, ABoxReachingBehindAPerspectiveEyeIsKept) {
  const glm::mat4 spot = glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 100.0f) *
                         glm::lookAt(glm::vec3(0.0f, 20.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  const ReceiverMask mask(spot, {});
  EXPECT_TRUE(mask.may_shadow(glm::vec3(0.0f, 20.0f, 0.0f), glm::vec3(2.0f), glm::mat4(1.0f)));
}

}  // namespace
}  // namespace pointgen
