#include "shadow/convex_body.hpp"

#include <gtest/gtest.h>

namespace {

TEST(ConvexBody, ClippingAUnitCubeByADiagonalPlaneKeepsOneHalf) {
  shadow::Box box;
  box.add(glm::vec3(0.0f));
  box.add(glm::vec3(1.0f));
  shadow::ConvexBody body = shadow::ConvexBody::from_box(box);
  body.clip(shadow::Plane::through(glm::vec3(0.5f), glm::vec3(1.0f, 1.0f, 1.0f)));
  for (const glm::vec3& p : body.vertices()) EXPECT_LE(p.x + p.y + p.z, 1.5f + 1e-5f);
  EXPECT_EQ(body.faces().size(), 7u);  // three whole faces, three cut faces, the cap
}

}  // namespace
