// What silhouette-edge shadow volumes stand on, against geometry the tests compute: every edge of
// a closed box with split vertices finds the face across it by position; an open quad's border
// edges have none and its diagonal joins its two triangles; the body between the camera's near
// plane and the light meets a box exactly where a box stands between them.
#include "pointgen/primitives.hpp"
#include "pointgen/triangle_adjacency.hpp"
#include "shadow/volume_counting.hpp"

#include <gtest/gtest.h>

#include <set>

namespace {

using pointgen::TriangleMesh;

// The third vertex of triangle t other than the edge's ends a and b.
std::uint32_t opposite(const TriangleMesh& mesh, std::size_t t, std::uint32_t a, std::uint32_t b) {
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t v = mesh.indices[3 * t + i];
    if (v != a && v != b) return v;
  }
  return a;
}

TEST(TriangleAdjacency, EveryEdgeOfAClosedBoxWithSplitVerticesFindsTheFaceAcrossIt) {
  const TriangleMesh box = pointgen::unit_box();
  ASSERT_GT(box.positions.size(), 8u);  // split: the faces do not share vertices
  const std::vector<std::uint32_t> adjacency = pointgen::adjacency_indices(box);
  ASSERT_EQ(adjacency.size(), 2 * box.indices.size());
  for (std::size_t t = 0; t < box.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const glm::vec3 a = box.positions[adjacency[6 * t + 2 * i]], b = box.positions[adjacency[6 * t + (2 * i + 2) % 6]];
      const glm::vec3 across = box.positions[adjacency[6 * t + 2 * i + 1]];
      const glm::vec3 own = box.positions[opposite(box, t, adjacency[6 * t + 2 * i], adjacency[6 * t + (2 * i + 2) % 6])];
      EXPECT_NE(across, own) << "triangle " << t << ", edge " << i;
      // The neighbour is a triangle of the box with the same edge: some other triangle has the
      // three positions a, b, across.
      int found = 0;
      for (std::size_t u = 0; u < box.triangle_count(); ++u) {
        std::set<std::tuple<float, float, float>> corners;
        for (int k = 0; k < 3; ++k) {
          const glm::vec3 p = box.positions[box.indices[3 * u + k]];
          corners.insert({p.x, p.y, p.z});
        }
        found += u != t && corners.count({a.x, a.y, a.z}) && corners.count({b.x, b.y, b.z}) &&
                 corners.count({across.x, across.y, across.z});
      }
      EXPECT_EQ(found, 1) << "triangle " << t << ", edge " << i;
    }
  }
}

TEST(TriangleAdjacency, AnOpenQuadsBorderHasNoNeighboursAndItsDiagonalJoinsItsTriangles) {
  TriangleMesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  const std::vector<std::uint32_t> a = pointgen::adjacency_indices(quad);
  // Triangle 0: edges 0-1 (border), 1-2 (border), 2-0 (the diagonal, across it vertex 3).
  EXPECT_EQ(a[1], 2u);
  EXPECT_EQ(a[3], 0u);
  EXPECT_EQ(a[5], 3u);
  // Triangle 1: edges 0-2 (the diagonal, across it vertex 1), 2-3 and 3-0 (border).
  EXPECT_EQ(a[7], 1u);
  EXPECT_EQ(a[9], 0u);
  EXPECT_EQ(a[11], 2u);
}

shadow::Box box_around(const glm::vec3& centre, float half) { return {centre - half, centre + half}; }

TEST(VolumeCounting, ABoxMeetsTheNearPlanesHullOnlyBetweenTheCameraAndTheLight) {
  shadow::Camera camera;
  camera.position = {0, 2, 10};
  camera.target = {0, 2, 0};
  camera.near = 0.1f;
  const shadow::Light sun{shadow::LightType::directional, {}, glm::normalize(glm::vec3(0, -1, -1)), 30};
  const shadow::Light lamp{shadow::LightType::point, {0, 12, 20}, {0, -1, 0}, 30};
  for (const shadow::Light& light : {sun, lamp}) {
    const std::vector<shadow::Plane> hull = shadow::near_plane_light_hull(camera, 16.0f / 9.0f, light);
    // Halfway from the eye to the light (both lights lie up and behind the camera).
    const glm::vec3 towards = light.type == shadow::LightType::point ? 0.5f * (light.position - camera.position)
                                                                     : -5.0f * light.direction;
    EXPECT_TRUE(shadow::meets(hull, box_around(camera.position + towards, 0.2f)));
    EXPECT_TRUE(shadow::meets(hull, box_around(camera.position + glm::vec3(0, 0, -0.1f), 0.02f)));  // on the near plane
    EXPECT_FALSE(shadow::meets(hull, box_around(camera.position - towards, 0.2f)));  // away from the light
    EXPECT_FALSE(shadow::meets(hull, box_around(camera.position + glm::vec3(3, 0, 0), 0.2f)));  // beside
    // A ground far wider than the hull, under it: outside none of its planes alone, yet apart.
    EXPECT_FALSE(shadow::meets(hull, {{-100, -0.1f, -100}, {100, 0, 100}}));
  }
}

}  // namespace
