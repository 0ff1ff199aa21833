// Grouping instances into cells for the sampler, and culling them by cells to a view.
#include "pointgen/random.hpp"
#include "pointgen/sampling/frustum_culling.hpp"
#include "pointgen/sampling/instance_cells.hpp"
#include "pointgen/sampling/view_sampler.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace pointgen {
namespace {

TEST(InstanceCells, HoldEveryInstanceOnceInBoxesAroundTheirSpheres) {
  SampledMesh mesh;
  mesh.center = {0.0f, 1.0f, 0.0f};
  mesh.radius = 1.5f;
  mesh.area = 3.0f;
  InstanceTable table;
  Random rng(21);
  for (int i = 0; i < 1000; ++i) {
    const glm::mat4 at = glm::translate(glm::mat4(1.0f), {rng.uniform(-50.0f, 50.0f), rng.uniform(0.0f, 5.0f), rng.uniform(-50.0f, 50.0f)});
    table.add(glm::scale(at, glm::vec3(rng.uniform(0.5f, 2.0f))), glm::vec3(1.0f), derive_seed(21, i));
  }
  InstanceCells cells(std::vector<InstanceTable>{table}, {mesh});
  ASSERT_EQ(cells.by_table().size(), 1u);
  std::vector<std::uint32_t> members;
  for (const InstanceCell& cell : cells.by_table()[0]) {
    EXPECT_EQ(cell.table, 0u);
    EXPECT_GE(cell.members.size(), InstanceCells::max_members / 2);
    EXPECT_LE(cell.members.size(), InstanceCells::max_members);
    float area = 0.0f;
    for (std::uint32_t i : cell.members) {
      members.push_back(i);
      const glm::mat4 m = table.transform(i);
      const float scale = m[0][0];
      const glm::vec3 center(m * glm::vec4(mesh.center, 1.0f));
      EXPECT_TRUE(glm::all(glm::lessThanEqual(cell.min, center - mesh.radius * scale + 1e-4f)));
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(cell.max, center + mesh.radius * scale - 1e-4f)));
      area += mesh.area * scale * scale;
    }
    EXPECT_NEAR(cell.area, area, 1e-3f * area);
  }
  std::sort(members.begin(), members.end());
  std::vector<std::uint32_t> all(1000);
  std::iota(all.begin(), all.end(), 0u);
  EXPECT_EQ(members, all) << "every instance in exactly one cell";
  // Split at medians: 1,000 instances in 16 cells of 62 or 63.
  EXPECT_EQ(cells.by_table()[0].size(), 16u);

  table.transforms.resize(10);
  table.tints.resize(10);
  table.seeds.resize(10);
  cells.update(0, table, mesh);
  ASSERT_EQ(cells.by_table()[0].size(), 1u);
  EXPECT_EQ(cells.by_table()[0][0].members.size(), 10u);
}

// Spheres of radius 1 on a 200 x 200 m square around a camera at the origin looking down -z with
// a 90° field of view and aspect 1: a sphere is in view when it reaches over |x| <= -z and
// |y| <= -z and in front of the near plane z = -0.1 (the far plane is beyond them all). Culled by
// cells, every such sphere must be found and no other.
TEST(InstancesInView, AreTheSpheresThatReachIntoTheFrustum) {
  SampledMesh mesh;
  mesh.radius = 1.0f;
  InstanceTable table;
  Random rng(22);
  for (int i = 0; i < 4000; ++i) {
    table.add(glm::translate(glm::mat4(1.0f), {rng.uniform(-100.0f, 100.0f), rng.uniform(-3.0f, 3.0f), rng.uniform(-100.0f, 100.0f)}),
              glm::vec3(1.0f), derive_seed(22, i));
  }
  const InstanceCells cells(std::vector<InstanceTable>{table}, {mesh});
  const glm::mat4 view = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 1000.0f);
  const std::vector<std::uint32_t> seen = instances_in_view(ViewFrusta({view}), cells.by_table()[0], table, mesh);
  std::vector<std::uint32_t> expected;
  const float reach = std::sqrt(2.0f);  // a side plane's normal is (1, 0, 1) / sqrt(2)
  for (std::uint32_t i = 0; i < table.size(); ++i) {
    const glm::vec3 c(table.transforms[i][3]);
    if (std::abs(c.x) <= -c.z + reach && std::abs(c.y) <= -c.z + reach && c.z <= 0.9f) expected.push_back(i);
  }
  EXPECT_GT(expected.size(), 500u);
  EXPECT_LT(expected.size(), 2000u);
  EXPECT_EQ(seen, expected);
}

}  // namespace
}  // namespace pointgen
