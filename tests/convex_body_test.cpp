// The convex-polyhedron clipper the focus bodies are cut with, against what geometry says of a
// cube cut by planes and moved by a projective matrix.
#include "random_setups.hpp"
#include "shadow/convex_body.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace shadow {
namespace {

Box unit_box() {
  Box b;
  b.add(glm::vec3(0.0f));
  b.add(glm::vec3(1.0f));
  return b;
}

// Whether every point of `a` is within eps of a point of `b`, and they have as many.
bool same_points(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b, float eps) {
  if (a.size() != b.size()) return false;
  for (const glm::vec3& p : a) {
    bool found = false;
    for (const glm::vec3& q : b) found = found || glm::distance(p, q) <= eps;
    if (!found) return false;
  }
  return true;
}

TEST(ConvexBody, PlaneMissingTheBodyKeepsItPlaneBeyondItEmptiesIt) {
  const ConvexBody cube = ConvexBody::from_box(unit_box());
  ConvexBody missed = cube;
  missed.clip(Plane::through({3, 0, 0}, {1, 1, 0}));  // x + y <= 3: all of the cube
  EXPECT_TRUE(same_points(missed.vertices(), cube.vertices(), 1e-6f));
  EXPECT_EQ(missed.faces().size(), 6u);
  ConvexBody excluded = cube;
  excluded.clip(Plane::through({-0.5f, 0, 0}, {1, 0, 0}));  // x <= -0.5: none of it
  EXPECT_TRUE(excluded.empty());
}

// A cube cut by random planes through its inside: every vertex keeps to the kept side of the
// cutting plane; every face plane has all vertices on or inside it and the centroid strictly
// inside (which holds only for outward normals); and the cap's face plane is the cutting plane.
TEST(ConvexBody, ClippedBodiesHaveOutwardFacePlanesAroundTheirCentroid) {
  pointgen::Random rng(502);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const Plane cut = Plane::through({rng.uniform(0.2f, 0.8f), rng.uniform(0.2f, 0.8f), rng.uniform(0.2f, 0.8f)}, random_unit(rng));
    ConvexBody body = ConvexBody::from_box(unit_box());
    body.clip(cut);
    ASSERT_FALSE(body.empty());
    const std::vector<glm::vec3> vertices = body.vertices();
    for (const glm::vec3& p : vertices) EXPECT_LE(cut.distance(p), 1e-5f);
    bool cap_found = false;
    for (const Plane& face : body.face_planes()) {
      for (const glm::vec3& p : vertices) EXPECT_LE(face.distance(p), 1e-5f) << "body " << i;
      EXPECT_LT(face.distance(body.centroid()), -1e-4f) << "body " << i;
      cap_found = cap_found || (glm::dot(face.normal, cut.normal) > 1.0f - 1e-5f && std::abs(face.offset - cut.offset) < 1e-5f);
      ++checked;
    }
    EXPECT_TRUE(cap_found) << "body " << i;
  }
  EXPECT_GT(checked, 200 * 4);
}

// Under a perspective projection each vertex must land where the matrix sends it, divided by w.
TEST(ConvexBody, ProjectiveTransformMovesVerticesLikeTheMatrix) {
  Box box;  // 5 to 20 m in front of a camera at the origin looking down -z
  box.add({-3, -2, -20});
  box.add({4, 3, -5});
  const glm::mat4 m = glm::perspective(glm::radians(60.0f), 1.3f, 1.0f, 50.0f) *
                      glm::lookAt(glm::vec3(0.5f, 0.2f, 0), glm::vec3(0, 0, -10), glm::vec3(0, 1, 0));
  const ConvexBody body = ConvexBody::from_box(box);
  std::vector<glm::vec3> expected;
  for (int i = 0; i < 8; ++i) expected.push_back(ndc(m, box.corner(i)));
  EXPECT_TRUE(same_points(body.transformed(m).vertices(), expected, 1e-5f));
  EXPECT_EQ(body.transformed(m).faces().size(), 6u);
}

TEST(ConvexBody, ClippingAUnitCubeByADiagonalPlaneKeepsOneHalf) {
  ConvexBody body = ConvexBody::from_box(unit_box());
  body.clip(Plane::through(glm::vec3(0.5f), glm::vec3(1.0f, 1.0f, 1.0f)));
  for (const glm::vec3& p : body.vertices()) EXPECT_LE(p.x + p.y + p.z, 1.5f + 1e-5f);
  EXPECT_EQ(body.faces().size(), 7u);  // three whole faces, three cut faces, the cap
}

}  // namespace
}  // namespace shadow
