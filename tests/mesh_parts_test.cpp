// Splitting a point mesh into parts, and the sampler counting a large near instance by its parts.
#include "pointgen/random.hpp"
#include "pointgen/sampling/mesh_parts.hpp"
#include "pointgen/sampling/view_sampler.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <array>
#include <numeric>

namespace pointgen {
namespace {

std::vector<glm::vec3> random_points(std::size_t n, glm::vec3 size, std::uint64_t seed) {
  Random rng(seed);
  std::vector<glm::vec3> points(n);
  for (glm::vec3& p : points) p = glm::vec3(rng.uniform(), rng.uniform(), rng.uniform()) * size;
  return points;
}

TEST(MeshParts, PartsHoldEverySampleOnceInTheWholeListsOrderInDisjointBoxes) {
  const std::vector<glm::vec3> points = random_points(5000, {4.0f, 8.0f, 2.0f}, 3);
  const std::vector<glm::vec3> normals(points.size(), glm::vec3(0.0f, 1.0f, 0.0f));
  const MeshSplit split = split_into_parts(points, normals, 10.0f);
  ASSERT_EQ(split.order.size(), points.size());
  std::vector<std::uint32_t> sorted = split.order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::uint32_t> all(points.size());
  std::iota(all.begin(), all.end(), 0u);
  EXPECT_EQ(sorted, all) << "every sample in exactly one part";
  EXPECT_EQ(split.parts.size(), 64u);
  float area = 0.0f;
  for (const MeshPart& part : split.parts) {
    area += part.area;
    ASSERT_GE(part.first, points.size());
    const std::uint32_t begin = part.first - static_cast<std::uint32_t>(points.size());
    for (std::uint32_t k = begin; k < begin + part.samples; ++k) {
      const glm::vec3 p = points[split.order[k]];
      EXPECT_TRUE(glm::all(glm::lessThanEqual(glm::abs(p - part.center), part.half_size + 1e-5f)));
      // In the whole list's order: a prefix of the part's list is what a prefix of the whole list
      // holds of the part.
      if (k > begin) {
        EXPECT_LT(split.order[k - 1], split.order[k]);
      }
    }
    EXPECT_NEAR(part.radius, glm::length(part.half_size), 1e-5f);
    EXPECT_EQ(part.normal_moments, glm::mat3(0, 0, 0, 0, 1, 0, 0, 0, 0)) << "every normal along y";
  }
  EXPECT_NEAR(area, 10.0f, 1e-3f);
  for (std::size_t a = 0; a < split.parts.size(); ++a) {
    for (std::size_t b = a + 1; b < split.parts.size(); ++b) {
      const glm::vec3 gap = glm::abs(split.parts[a].center - split.parts[b].center) - split.parts[a].half_size - split.parts[b].half_size;
      EXPECT_GE(glm::max(gap.x, glm::max(gap.y, gap.z)), -1e-5f) << "parts " << a << " and " << b << " overlap";
    }
  }
}

TEST(MeshParts, TrianglePartsHoldEveryTriangleOnceInsideTheirBoxes) {
  TriangleMesh mesh;
  mesh.positions = random_points(600, {4.0f, 8.0f, 2.0f}, 5);
  Random rng(6);
  for (int t = 0; t < 900; ++t) {
    for (int corner = 0; corner < 3; ++corner) mesh.indices.push_back(rng.below(static_cast<std::uint32_t>(mesh.positions.size())));
  }
  const TriangleSplit split = split_triangles(mesh);
  ASSERT_EQ(split.indices.size(), mesh.indices.size());
  ASSERT_LE(split.parts.size(), 64u);
  ASSERT_GT(split.parts.size(), 1u);
  const auto triangles_of = [](const std::vector<std::uint32_t>& indices) {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (std::size_t i = 0; i < indices.size(); i += 3) triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
    std::sort(triangles.begin(), triangles.end());
    return triangles;
  };
  EXPECT_EQ(triangles_of(split.indices), triangles_of(mesh.indices)) << "every triangle once, its corners in order";
  std::uint32_t next = 0;
  for (const PolygonPart& part : split.parts) {
    EXPECT_EQ(part.first_index, next) << "the parts follow each other";
    EXPECT_GT(part.index_count, 0u);
    EXPECT_EQ(part.index_count % 3, 0u);
    next = part.first_index + part.index_count;
    for (std::uint32_t i = part.first_index; i < next; ++i) {
      const glm::vec3 p = mesh.positions[split.indices[i]];
      EXPECT_TRUE(glm::all(glm::lessThanEqual(glm::abs(p - part.center), part.half_size + 1e-5f))) << "corner inside its part's box";
    }
  }
  EXPECT_EQ(next, split.indices.size());
}

// Two parallel 4 m plates 2 m apart, facing the camera (normals along z), as one mesh whose sample
// list (20,000, alternating plates) is followed by its parts' lists.
SampledMesh two_plates() {
  Random rng(9);
  SampledMesh mesh;
  for (int i = 0; i < 20000; ++i) mesh.sample_positions.emplace_back(rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f), i % 2 ? 1.0f : -1.0f);
  mesh.area = 32.0f;
  mesh.radius = glm::length(glm::vec3(2.0f, 2.0f, 1.0f));
  mesh.half_size = {2.0f, 2.0f, 1.0f};
  mesh.triangles = 1000000;
  mesh.samples = mesh.sample_positions.size();
  const std::vector<glm::vec3> normals(mesh.samples, glm::vec3(0.0f, 0.0f, 1.0f));
  mesh.normal_moments = glm::mat3(0, 0, 0, 0, 0, 0, 0, 0, 1);
  MeshSplit split = split_into_parts(mesh.sample_positions, normals, mesh.area);
  for (std::uint32_t i : split.order) mesh.sample_positions.push_back(mesh.sample_positions[i]);
  mesh.parts = std::move(split.parts);
  return mesh;
}

TEST(ViewSampler, ALargeNearInstanceCountedByPartsHidesItsBackBehindItsFront) {
  SamplerView view;
  view.views = {glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 1000.0f)};  // from the origin down -Z
  view.density = {256.0f, 2.0f};
  view.pixels = {512, 512};
  view.full_count_transmittance = 1.0f;  // counts follow the visible share
  InstanceTable table;
  table.add(glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -20.0f}), glm::vec3(1.0f), 7);
  SampledMesh mesh = two_plates();
  const SampledFrame parts = sample_view(view, std::vector<InstanceTable>{table}, {mesh});
  std::size_t front = 0, back = 0;
  for (const PointDraw& d : parts.points) {
    ASSERT_GE(d.first, mesh.samples) << "drawn from the parts' lists";
    const float z = mesh.sample_positions[d.first].z;
    (z > 0.0f ? front : back) += d.count;
    for (std::uint32_t k = d.first; k < d.first + d.count; ++k) ASSERT_EQ(mesh.sample_positions[k].z, z) << "one plate per part";
  }
  // Whole, the instance takes n = k rho^2 A f d / z^3 = 2 * 256^2 * 32 * 1 / 20^2 = 10,486 points
  // (facing the eye: f = 1; no occlusion by others); by parts, the front plate takes about half of
  // it, 2 * 256^2 * 16 / 19^2 = 5,809 (a little less: each part's rectangle shares its edges with
  // neighbours counted before it, whose splats already cover some of them), and hides the back.
  mesh.parts.clear();
  const SampledFrame whole = sample_view(view, std::vector<InstanceTable>{table}, {mesh});
  ASSERT_EQ(whole.points.size(), 1u);
  EXPECT_NEAR(static_cast<double>(whole.point_count), 10486.0, 2.0);
  EXPECT_NEAR(static_cast<double>(front), 5809.0, 0.1 * 5809.0);
  EXPECT_LT(back, front / 10) << "the back plate is behind the front one";
}

// A grid of n x n points over x in [x0, x1], y in [-h, h] at z = 0 (a mesh's frame).
std::vector<glm::vec3> grid_points(float x0, float x1, float h, int n) {
  std::vector<glm::vec3> points;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) points.emplace_back(x0 + (x1 - x0) * (i + 0.5f) / n, -h + 2.0f * h * (j + 0.5f) / n, 0.0f);
  }
  return points;
}

// A screen over x in [-1.6, 0], y in [-1.6, 1.6] at z = 0 (its frame): a grid of n x n samples,
// drawn as points.
SampledMesh left_screen(int n, float area) {
  SampledMesh screen;
  screen.sample_positions = grid_points(-1.6f, 0.0f, 1.6f, n);
  screen.area = area;
  screen.samples = 500000;
  screen.triangles = 1000000;
  screen.center = {-0.8f, 0.0f, 0.0f};
  screen.half_size = {0.8f, 1.6f, 0.0f};
  screen.radius = glm::length(screen.half_size);
  return screen;
}

// Table 0: the plates (mesh 0) `plates_at` metres ahead; table 1: the screen (mesh 1) `screen_at`.
std::vector<InstanceTable> plates_and_screen(float plates_at, float screen_at) {
  std::vector<InstanceTable> tables(2);
  tables[0].add(glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -plates_at}), glm::vec3(1.0f), 7);
  tables[1].mesh = 1;
  tables[1].add(glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -screen_at}), glm::vec3(1.0f), 8);
  return tables;
}

TEST(ViewSampler, AnInstanceLeftWholeForPolygonsIsCountedByPartsOnceItsHiddenShareMakesItPoints) {
  SamplerView view;
  view.views = {glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 1000.0f)};
  view.density = {256.0f, 2.0f};
  view.pixels = {512, 512};
  view.full_count_transmittance = 1.0f;
  // Unhidden, the plates take 10,486 points (above), in the band around their polygons' 12,000:
  // left whole. A screen 10 m away hides the left half of them (x < 0 in their frame).
  SampledMesh plates = two_plates();
  plates.triangles = 3000;
  // 1.7 pixels apart or less: 2-pixel splats cover it; its area asks for all of its grid.
  const SampledMesh screen = left_screen(48, 400.0f);
  std::vector<InstanceTable> tables = plates_and_screen(20.0f, 10.0f);
  const SampledFrame f = sample_view(view, tables, {plates, screen});
  std::size_t left = 0, right = 0;
  for (const PointDraw& d : f.points) {
    if (d.table != 0) continue;
    ASSERT_GE(d.first, plates.samples) << "drawn from the parts' lists";
    for (std::uint32_t k = d.first; k < d.first + d.count; ++k) (plates.sample_positions[k].x < 0.0f ? left : right) += 1;
  }
  EXPECT_TRUE(f.polygons[0].empty());
  EXPECT_GT(right, 2000u) << "the front plate's right half: about 2 * 256^2 * 8 / 19^2 = 2,900";
  EXPECT_LT(left, right / 20) << "the hidden half";
}

TEST(ViewSampler, AnInstanceDrawnAsPolygonsDrawsThePartsThatNearerObjectsLeaveToBeSeen) {
  SamplerView view;
  view.views = {glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 1000.0f)};
  view.density = {256.0f, 2.0f};
  view.pixels = {512, 512};
  // The plates 12 m away need 2 * 256^2 * 32 / 12^2 = 29,000 points, more than their polygons'
  // 12,000: polygons, in a left and a right half. A screen 6 m away hides the left half's box
  // (x in [-2/11, 0] on screen, the screen covering [-1.6/6, 0]).
  SampledMesh plates = two_plates();
  plates.triangles = 3000;
  plates.polygon_parts = {{0, 4500, {-1.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 1.0f}}, {4500, 4500, {1.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 1.0f}}};
  // 1.4 pixels apart or less: 2-pixel splats cover it. Points: 2 * 256^2 * 100 * 0.5 / 6^2 =
  // 182,000, fewer than its list and its polygons cost.
  const SampledMesh screen = left_screen(96, 100.0f);
  std::vector<InstanceTable> tables = plates_and_screen(12.0f, 6.0f);
  const SampledFrame hidden_left = sample_view(view, tables, {plates, screen});
  ASSERT_EQ(hidden_left.polygons[0], (std::vector<std::uint32_t>{0}));
  ASSERT_EQ(hidden_left.polygon_parts[0].size(), 1u);
  EXPECT_EQ(hidden_left.polygon_parts[0][0], 0b10u) << "the right half only";
  EXPECT_EQ(hidden_left.triangle_count, 1500u);
  tables[1].transforms[0] = glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, 5.0f});  // behind the eye
  const SampledFrame unhidden = sample_view(view, tables, {plates, screen});
  ASSERT_EQ(unhidden.polygon_parts[0].size(), 1u);
  EXPECT_EQ(unhidden.polygon_parts[0][0], 0b11u);
  EXPECT_EQ(unhidden.triangle_count, 3000u);
}

TEST(ViewSampler, AnInstanceWhoseSphereReachesIntoTheViewButNotItsBoxGetsNothing) {
  SamplerView view;
  view.views = {glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 1000.0f)};
  view.density = {256.0f, 2.0f};
  view.pixels = {512, 512};
  // A long thin mesh along y: its sphere is wide, its box is not. At x = 21 m, 20 m ahead, the
  // sphere crosses the view's right edge (x = 20 m there); the box, 0.5 m wide, stays outside it.
  SampledMesh pole;
  pole.sample_positions = grid_points(-0.25f, 0.25f, 3.0f, 16);
  pole.area = 3.0f;
  pole.samples = pole.sample_positions.size();
  pole.triangles = 100000;
  pole.half_size = {0.25f, 3.0f, 0.25f};
  pole.radius = glm::length(pole.half_size);
  InstanceTable table;
  table.add(glm::translate(glm::mat4(1.0f), {21.0f, 0.0f, -20.0f}), glm::vec3(1.0f), 3);
  const SampledFrame f = sample_view(view, std::vector<InstanceTable>{table}, {pole});
  EXPECT_TRUE(f.points.empty());
  EXPECT_TRUE(f.polygons[0].empty());
}

}  // namespace
}  // namespace pointgen
