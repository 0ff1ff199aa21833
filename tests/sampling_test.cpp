// Surface samples and the view-adaptive count, against facts computed here.
#include "pointgen/primitives.hpp"
#include "pointgen/random.hpp"
#include "pointgen/sampling/coverage_grid.hpp"
#include "pointgen/sampling/point_count.hpp"
#include "pointgen/sampling/surface_samples.hpp"
#include "pointgen/sampling/view_sampler.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pointgen {
namespace {

// Two separate triangles in the plane y = 0: one of area 0.5 around x in [0, 1], one of area 1.5
// around x in [10, 13]; corner colours red, green, blue.
TriangleMesh two_triangles() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {10, 0, 0}, {13, 0, 0}, {10, 0, 1}};
  m.normals.assign(6, glm::vec3(0, 1, 0));
  m.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.indices = {0, 2, 1, 3, 5, 4};
  return m;
}

double share_in_big(const std::vector<SurfaceSample>& s, std::size_t n) {
  std::size_t big = 0;
  for (std::size_t i = 0; i < n; ++i) big += s[i].position.x >= 10.0f;
  return static_cast<double>(big) / static_cast<double>(n);
}

TEST(SurfaceSamples, TrianglesAreHitInProportionToTheirAreaInEveryPrefix) {
  const std::vector<SurfaceSample> s = sample_surface(two_triangles(), 40000, 1);
  ASSERT_EQ(s.size(), 40000u);
  for (std::size_t n : {400u, 4000u, 40000u}) {
    const double sd = std::sqrt(0.75 * 0.25 / static_cast<double>(n));
    EXPECT_NEAR(share_in_big(s, n), 0.75, 4.5 * sd) << "prefix of " << n;
  }
}

TEST(SurfaceSamples, PointsAreUniformInsideEachTriangleWithInterpolatedAttributes) {
  const std::vector<SurfaceSample> s = sample_surface(two_triangles(), 20000, 2);
  glm::dvec3 mean(0.0);
  std::size_t small = 0;
  for (const SurfaceSample& p : s) {
    if (p.position.x >= 10.0f) continue;
    ++small;
    EXPECT_GE(p.position.x, 0.0f);
    EXPECT_GE(p.position.z, 0.0f);
    EXPECT_LE(p.position.x + p.position.z, 1.0f + 1e-5f);
    // Colours are the barycentric weights of the corners: green grows with x, blue with z.
    EXPECT_NEAR(p.color.g, p.position.x, 1e-4f);
    EXPECT_NEAR(p.color.b, p.position.z, 1e-4f);
    EXPECT_NEAR(p.color.r, 1.0f - p.position.x - p.position.z, 1e-4f);
    mean += glm::dvec3(p.position);
  }
  mean /= static_cast<double>(small);
  // The centroid of the triangle (0,0)-(1,0)-(0,1) is (1/3, 1/3); the mean's sd is about 0.24/sqrt(n).
  EXPECT_NEAR(mean.x, 1.0 / 3.0, 0.01);
  EXPECT_NEAR(mean.z, 1.0 / 3.0, 0.01);
}

TEST(SurfaceSamples, SameSeedSameListOtherSeedOtherList) {
  const TriangleMesh box = unit_box();
  const auto a = sample_surface(box, 100, 7), b = sample_surface(box, 100, 7), c = sample_surface(box, 100, 8);
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(SurfaceSample)));
  EXPECT_NE(0, std::memcmp(a.data(), c.data(), a.size() * sizeof(SurfaceSample)));
  for (const SurfaceSample& p : a) {
    EXPECT_NEAR(std::max({std::abs(p.position.x), std::abs(p.position.y), std::abs(p.position.z)}), 0.5f, 1e-5f);
  }
}

// A flat grid of `side` × `side` unit squares in y = 0, two triangles each, all of area 1/2.
TriangleMesh flat_grid(int side) {
  TriangleMesh m;
  for (int z = 0; z <= side; ++z) {
    for (int x = 0; x <= side; ++x) m.positions.emplace_back(x, 0, z);
  }
  m.normals.assign(m.positions.size(), glm::vec3(0, 1, 0));
  m.colors.assign(m.positions.size(), glm::vec3(1));
  const auto at = [side](int x, int z) { return static_cast<std::uint32_t>(z * (side + 1) + x); };
  for (int z = 0; z < side; ++z) {
    for (int x = 0; x < side; ++x) m.indices.insert(m.indices.end(), {at(x, z), at(x, z + 1), at(x + 1, z), at(x + 1, z), at(x, z + 1), at(x + 1, z + 1)});
  }
  return m;
}

// Independent draws would give each of 128 triangles a count scattered by the square root of its
// share (10 at a share of 100, the largest of 128 off by about 25; 15 and 30 off at shares of 20
// and 100 with the former sampler); the list's prefixes keep every count within two of its share,
// and leave no square of the grid empty once it is due 6 points.
TEST(SurfaceSamples, EveryPrefixCoversTheSurfaceEvenly) {
  const int side = 8, triangles = 2 * side * side;
  const std::vector<SurfaceSample> s = sample_surface(flat_grid(side), 100 * triangles, 3);
  for (std::size_t n : {static_cast<std::size_t>(3 * triangles), static_cast<std::size_t>(20 * triangles), s.size()}) {
    std::vector<int> per_square(side * side, 0), per_triangle(triangles, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const glm::vec3 p = s[i].position;
      const int x = std::min(side - 1, static_cast<int>(p.x)), z = std::min(side - 1, static_cast<int>(p.z));
      const bool upper = (p.x - x) + (p.z - z) > 1.0f;
      ++per_square[z * side + x];
      ++per_triangle[2 * (z * side + x) + upper];
    }
    const double share = static_cast<double>(n) / triangles;
    int worst = 0;
    for (int c : per_triangle) worst = std::max(worst, static_cast<int>(std::ceil(std::abs(c - share))));
    EXPECT_LE(worst, 2) << "prefix of " << n << ": a triangle's count is " << worst << " off its share " << share;
    EXPECT_GT(*std::min_element(per_square.begin(), per_square.end()), 0) << "prefix of " << n;
  }
}

TEST(SurfaceArea, OfKnownShapes) {
  EXPECT_NEAR(surface_area(unit_box()), 6.0f, 1e-4f);
  EXPECT_NEAR(surface_area(two_triangles()), 2.0f, 1e-5f);
  EXPECT_NEAR(surface_area(unit_sphere(96, 48)), 4.0f * 3.14159265f, 0.02f);
}

TEST(PointCount, MatchesThePixelAreaOfASmallSquareFacingTheCamera) {
  // A 0.1 m square facing the camera 10 m ahead covers (0.01 / 100) * rho^2 pixels; randomly
  // oriented two-sided surfaces cover half as much on average, so k points per pixel of that.
  const PointDensity density{500.0f, 2.0f};
  const float pixels_if_facing = 0.01f / 100.0f * 500.0f * 500.0f;
  EXPECT_NEAR(points_needed(density, 0.01f, 10.0f, 10.0f), 2.0f * 0.5f * pixels_if_facing, 1e-3f);
  // Twice as far: a quarter. Off axis at the same depth (distance > depth): more, by d / z.
  EXPECT_NEAR(points_needed(density, 0.01f, 20.0f, 20.0f), 0.25f * points_needed(density, 0.01f, 10.0f, 10.0f), 1e-3f);
  EXPECT_NEAR(points_needed(density, 0.01f, 10.0f, 12.0f), 1.2f * points_needed(density, 0.01f, 10.0f, 10.0f), 1e-3f);
}

TEST(PointCount, FacingIsTheRootMeanSquareOfTheNormalsTowardsTheEye) {
  // A flat surface: |n . v| itself, and the count follows it (1/2 is the default).
  const glm::mat3 flat = normal_moments(std::vector<glm::vec3>{{0, 0, 1}, {0, 0, -1}});
  EXPECT_NEAR(facing(flat, {0, 0, 1}), 1.0f, 1e-6f);
  EXPECT_NEAR(facing(flat, {1, 0, 0}), 0.0f, 1e-6f);
  EXPECT_NEAR(facing(flat, glm::normalize(glm::vec3(std::sqrt(3.0f), 0, 1))), 0.5f, 1e-6f);
  const PointDensity density{500.0f, 2.0f};
  EXPECT_NEAR(points_needed(density, 0.01f, 10.0f, 10.0f, 1.0f), 2.0f * points_needed(density, 0.01f, 10.0f, 10.0f), 1e-3f);
  // Normals every way: 1/sqrt(3) (their mean |n . v| is 1/2); unknown moments: 1/2.
  Random rng(4);
  std::vector<glm::vec3> normals;
  while (normals.size() < 20000) {
    const glm::vec3 p(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f));
    if (glm::dot(p, p) <= 1.0f && glm::dot(p, p) > 1e-4f) normals.push_back(glm::normalize(p));
  }
  EXPECT_NEAR(facing(normal_moments(normals), glm::normalize(glm::vec3(1, 2, 3))), 1.0f / std::sqrt(3.0f), 0.01f);
  EXPECT_EQ(facing(glm::mat3(0.0f), {0, 0, 1}), 0.5f);
}

}  // namespace
}  // namespace pointgen

namespace pointgen {
namespace {

// A camera at the origin looking down -Z with a 90° vertical field of view, square image.
SamplerView test_view() {
  SamplerView v;
  v.views = {glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 1000.0f)};
  v.density = {256.0f, 2.0f};  // 512 pixels high
  v.points_per_triangle = 4.0f;
  v.occlusion = false;  // counts of whole instances; the occlusion tests turn it on
  return v;
}

InstanceTable table_at(const std::vector<glm::vec3>& positions) {
  InstanceTable t;
  for (const glm::vec3& p : positions) t.add(glm::translate(glm::mat4(1.0f), p), glm::vec3(1.0f), 0);
  return t;
}

TEST(ViewSampler, CullsWhatIsOutOfViewAndCountsTheRest) {
  const SampledMesh mesh{2.0f, glm::vec3(0.0f), 0.5f, 1000, 5000, glm::vec3(0.5f), {}, {}, glm::mat3(0.0f), {}};  // 2 m² in 1,000 triangles: break-even at 4,000 points
  const SampledFrame f = sample_view(test_view(), std::vector<InstanceTable>{table_at({{0, 0, 40}, {0, 0, -40}, {100, 0, -40}})}, {mesh});
  ASSERT_EQ(f.points.size(), 1u) << "the instances behind and beside the view are culled";
  EXPECT_EQ(f.points[0].instance, 1u);
  // n = k rho^2 A d / (2 z^3) with z = d = 40 m at the instance's centre, rounded either way.
  const float n = 2.0f * 256.0f * 256.0f * 2.0f / (2.0f * 40.0f * 40.0f);
  EXPECT_GE(f.points[0].count, static_cast<std::uint32_t>(std::floor(n)));
  EXPECT_LE(f.points[0].count, static_cast<std::uint32_t>(std::ceil(n)));
  EXPECT_TRUE(f.polygons[0].empty());
}

TEST(ViewSampler, NearInstancesArePolygonsAndTheBandBetweenDrawsBoth) {
  const SampledMesh mesh{2.0f, glm::vec3(0.0f), 0.5f, 1000, 5000, glm::vec3(0.5f), {}, {}, glm::mat3(0.0f), {}};
  // Points needed = 131072 / z^2: 4,000 (break-even) at z = 5.7 m; the band is 5.1 to 6.4 m.
  const SampledFrame f = sample_view(test_view(), std::vector<InstanceTable>{table_at({{0, 0, -3.5f}, {0, 0, -5.8f}, {0, 0, -9.5f}})}, {mesh});
  ASSERT_EQ(f.polygons[0], (std::vector<std::uint32_t>{0, 1}));
  ASSERT_EQ(f.points.size(), 2u);
  EXPECT_EQ(f.points[0].instance, 1u) << "in the band the instance is drawn both ways";
  // Its points thin out across the band: at the ratio 3,896 / 4,000 of needed points to the
  // polygon equivalent, (1.25 - ratio) / (1.25 - 0.8) of them.
  const float needed = 131072.0f / (5.8f * 5.8f);
  EXPECT_NEAR(static_cast<float>(f.points[0].count), needed * (1.25f - needed / 4000.0f) / 0.45f, 1.0f);
  EXPECT_EQ(f.points[1].instance, 2u);
  EXPECT_EQ(f.triangle_count, 2000u);
}

TEST(ViewSampler, CountsOfSmallInstancesAreRoundedWithoutBias) {
  // 4,000 instances needing 0.3 points each: some get one point, most none, about 1,200 in all.
  const SampledMesh mesh{2.0f, glm::vec3(0.0f), 0.5f, 1000, 5000, glm::vec3(0.5f), {}, {}, glm::mat3(0.0f), {}};
  InstanceTable table;
  for (int i = 0; i < 4000; ++i) table.add(glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -200.0f}), glm::vec3(1.0f), derive_seed(5, i));
  SamplerView view = test_view();
  view.density.k = 0.3f * 2.0f * 200.0f * 200.0f / (256.0f * 256.0f * 2.0f);
  const SampledFrame f = sample_view(view, std::vector<InstanceTable>{table}, {mesh});
  EXPECT_NEAR(static_cast<double>(f.point_count), 1200.0, 4.0 * std::sqrt(4000 * 0.3 * 0.7));
}

// A landscape's far picks each stand for several plants: every one in view draws a point, alone or
// in a far cell, however little it asks; the same table rounding as others draws about 30 %.
TEST(ViewSampler, InstancesThatRoundUpDrawAPointEachInViewHoweverLittleTheyAsk) {
  const SampledMesh mesh{2.0f, glm::vec3(0.0f), 0.5f, 1000, 5000, glm::vec3(0.5f), {}, {}, glm::mat3(0.0f), {}};
  InstanceTable table;
  Random rng(9);
  for (int i = 0; i < 4000; ++i) {
    table.add(glm::translate(glm::mat4(1.0f), {rng.uniform(-10.0f, 10.0f), rng.uniform(-10.0f, 10.0f), rng.uniform(-210.0f, -190.0f)}),
              glm::vec3(1.0f), derive_seed(9, i));
  }
  table.add(glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, 50.0f}), glm::vec3(1.0f), 1);  // behind the eye
  SamplerView view = test_view();
  view.density.k = 0.3f * 2.0f * 200.0f * 200.0f / (256.0f * 256.0f * 2.0f);  // 0.3 points each
  const SampledFrame rounding = sample_view(view, std::vector<InstanceTable>{table}, {mesh});
  EXPECT_NEAR(static_cast<double>(rounding.point_count), 1200.0, 200.0);
  table.rounds_up = true;
  const SampledFrame up = sample_view(view, std::vector<InstanceTable>{table}, {mesh});
  EXPECT_EQ(up.point_count, 4000u);
  for (const PointDraw& d : up.points) EXPECT_EQ(d.count, 1u);
}

TEST(ViewSampler, AFarCellIsCountedWholeWithOnePointForEachOfAsManyInstancesAsItNeeds) {
  // 20,000 instances on a 20 m square 400 m ahead, each needing about a quarter of a point.
  const SampledMesh mesh{2.0f, glm::vec3(0.0f), 0.5f, 1000, 5000, glm::vec3(0.5f), {}, {}, glm::mat3(0.0f), {}};
  InstanceTable table;
  Random rng(12);
  for (int i = 0; i < 20000; ++i) {
    table.add(glm::translate(glm::mat4(1.0f), {rng.uniform(-10.0f, 10.0f), rng.uniform(-10.0f, 10.0f), rng.uniform(-410.0f, -390.0f)}),
              glm::vec3(1.0f), derive_seed(12, i));
  }
  SamplerView view = test_view();
  view.density.k = 0.6f;
  double expected = 0.0;
  for (const glm::mat4x3& m : table.transforms) {
    const glm::vec3 p(m[3]);
    expected += points_needed(view.density, mesh.area, -p.z, glm::length(p));
  }
  const SampledFrame f = sample_view(view, std::vector<InstanceTable>{table}, {mesh});
  EXPECT_NEAR(static_cast<double>(f.point_count), expected, 0.02 * expected + 4.0 * std::sqrt(expected)) << "about 5,000";
  std::vector<std::uint32_t> drawn;
  std::size_t offset = 0;
  for (const PointDraw& d : f.points) {
    EXPECT_EQ(d.count, 1u);
    EXPECT_LT(d.first, mesh.samples);
    offset += d.first > 0;
    drawn.push_back(d.instance);
  }
  // Each at its own place in its list (an instance counted alone would draw the first sample).
  EXPECT_GT(offset, f.points.size() * 9 / 10);
  std::sort(drawn.begin(), drawn.end());
  EXPECT_EQ(std::adjacent_find(drawn.begin(), drawn.end()), drawn.end()) << "one point per chosen instance";
  const SampledFrame again = sample_view(view, std::vector<InstanceTable>{table}, {mesh});
  ASSERT_EQ(again.points.size(), f.points.size());
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    EXPECT_TRUE(again.points[i].instance == f.points[i].instance && again.points[i].first == f.points[i].first);
  }
}

// Points over the face z = 2 of a 4 m box around the origin, on a grid: 64 x 64, or only the
// columns with x < 0.
std::vector<glm::vec3> face_points(bool left_half_only) {
  std::vector<glm::vec3> points;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const glm::vec3 p(-2.0f + 4.0f * (i + 0.5f) / 64.0f, -2.0f + 4.0f * (j + 0.5f) / 64.0f, 2.0f);
      if (!left_half_only || p.x < 0.0f) points.push_back(p);
    }
  }
  return points;
}

TEST(ViewSampler, InstancesHiddenBehindOthersGetNoPoints) {
  // A 4 m box 10 m ahead whose points fill its front face; behind it at 40 m one small ball
  // straight back, one off to the side.
  SampledMesh opaque{400.0f, glm::vec3(0.0f), 3.5f, 100000, 500000, glm::vec3(2.0f), face_points(false), {}, glm::mat3(0.0f), {}};
  const SampledMesh small{0.3f, glm::vec3(0.0f), 0.5f, 1000, 5000, glm::vec3(0.3f), {glm::vec3(0.0f)}, {}, glm::mat3(0.0f), {}};
  std::vector<InstanceTable> tables = {table_at({{0, 0, -40}, {25, 0, -40}}), table_at({{0, 0, -10}})};
  tables[1].mesh = 1;
  SamplerView view = test_view();
  view.pixels = {512, 512};
  const auto count_of = [](const SampledFrame& f, std::uint32_t table, std::uint32_t instance) {
    for (const PointDraw& d : f.points) {
      if (d.table == table && d.instance == instance) return d.count;
    }
    return 0u;
  };
  const SampledFrame whole = sample_view(view, tables, {small, opaque});
  view.occlusion = true;
  const SampledFrame seen = sample_view(view, tables, {small, opaque});
  EXPECT_GT(count_of(whole, 0, 0), 5u);  // about 12
  EXPECT_EQ(count_of(seen, 0, 0), 0u) << "straight behind the box";
  EXPECT_EQ(count_of(seen, 0, 1), count_of(whole, 0, 1)) << "beside it";
  EXPECT_EQ(count_of(seen, 1, 0), count_of(whole, 1, 0)) << "the box itself is in front";
  // Points on the left half only: the right half of the ball shows, far above the fade-out.
  opaque.sample_positions = face_points(true);
  const SampledFrame through = sample_view(view, tables, {small, opaque});
  EXPECT_EQ(count_of(through, 0, 0), count_of(whole, 0, 0));
}

TEST(CoverageGrid, CellsAndTilesKeepWhatIsLeftUncovered) {
  CoverageGrid grid(glm::mat4(1.0f), {16, 16});  // cells 0.125 x 0.125 in NDC, read one by one
  const CoverageGrid::Rect corner_block{{-1.0f, -1.0f}, {-0.5f, -0.5f}};  // 4 x 4 cells
  // NDC (-0.8, -0.9) is cell (1.6, 0.8) of the grid: cell (1, 0).
  const std::vector<glm::vec3> point = {{-0.8f, -0.9f, 0.0f}};
  grid.cover(point, glm::mat4(1.0f));
  EXPECT_NEAR(grid.transmittance(corner_block), 15.0f / 16.0f, 1e-6f);
  grid.cover(std::vector<glm::vec3>{{-0.79f, -0.89f, 0.0f}}, glm::mat4(1.0f));
  EXPECT_NEAR(grid.transmittance(corner_block), 15.0f / 16.0f, 1e-6f) << "a covered cell stays covered once";
  EXPECT_NEAR(grid.transmittance({{-0.875f, -1.0f}, {-0.75f, -0.875f}}), 0.0f, 1e-6f) << "that cell alone";
  EXPECT_NEAR(grid.transmittance({{-0.875f, -1.0f}, {-0.625f, -0.875f}}), 0.5f, 1e-6f) << "it and the next";
  grid.cover(std::vector<glm::vec3>{{-0.6f, -0.6f, 0.0f}}, glm::mat4(1.0f));
  EXPECT_NEAR(grid.transmittance(corner_block), 14.0f / 16.0f, 1e-6f);
  // Moved by the transform a screen's width to the right: the same cell of the third block.
  grid.cover(point, glm::translate(glm::mat4(1.0f), {1.0f, 0.0f, 0.0f}));
  EXPECT_NEAR(grid.transmittance({{0.0f, -1.0f}, {0.5f, -0.5f}}), 15.0f / 16.0f, 1e-6f);
  EXPECT_NEAR(grid.transmittance({{-0.5f, -1.0f}, {0.0f, -0.5f}}), 1.0f, 1e-6f) << "the block between";
  // A rectangle over the first block and half of the one above it: the mean by area.
  EXPECT_NEAR(grid.transmittance({{-1.0f, -1.0f}, {-0.5f, -0.25f}}), (14.0f / 16.0f + 0.5f) / 1.5f, 1e-6f);
  // Off screen: nothing.
  grid.cover(std::vector<glm::vec3>{{1.0f, 0.0f, 0.0f}, {3.0f, 0.0f, 0.0f}, {0.0f, -1.01f, 0.0f}}, glm::mat4(1.0f));
  EXPECT_NEAR(grid.transmittance({{-1.0f, -1.0f}, {1.0f, 1.0f}}), (14.0f / 16.0f + 15.0f / 16.0f + 14.0f) / 16.0f, 1e-6f);
  // A large rectangle reads whole tiles of 8 x 8 cells: a covered cell just outside it, in a tile
  // it reaches into by a quarter of each side, counts a sixteenth.
  CoverageGrid large(glm::mat4(1.0f), {64, 64});
  const float cell = 2.0f / 64.0f;
  large.cover(std::vector<glm::vec3>{{-1.0f + 19.5f * cell, -1.0f + 19.5f * cell, 0.0f}}, glm::mat4(1.0f));
  EXPECT_NEAR(large.transmittance({{-1.0f, -1.0f}, {-1.0f + 18.0f * cell, -1.0f + 18.0f * cell}}), 1.0f - 0.0625f / 64.0f / 5.0625f, 1e-6f);
  // A 2 x 2 splat covers the cells the shaders' splat covers: from floor(position - 0.5).
  CoverageGrid splats(glm::mat4(1.0f), {16, 16}, 2);
  const auto cell_rect = [](int x, int y) {
    return CoverageGrid::Rect{{-1.0f + x / 8.0f, -1.0f + y / 8.0f}, {-1.0f + (x + 1) / 8.0f, -1.0f + (y + 1) / 8.0f}};
  };
  splats.cover(std::vector<glm::vec3>{{5.3f / 8.0f - 1.0f, 7.8f / 8.0f - 1.0f, 0.0f}, {0.2f / 8.0f - 1.0f, 0.2f / 8.0f - 1.0f, 0.0f}},
               glm::mat4(1.0f));
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const bool covered = (x >= 4 && x <= 5 && y >= 7 && y <= 8) || (x == 0 && y == 0);
      EXPECT_EQ(splats.transmittance(cell_rect(x, y)), covered ? 0.0f : 1.0f) << "cell " << x << ", " << y;
    }
  }
  // Behind the eye: nothing, and a box reaching behind it has no rectangle.
  CoverageGrid perspective(glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f), {16, 16});
  perspective.cover(std::vector<glm::vec3>{{0.0f, 0.0f, 5.0f}}, glm::mat4(1.0f));
  EXPECT_NEAR(perspective.transmittance({{-1.0f, -1.0f}, {1.0f, 1.0f}}), 1.0f, 1e-6f);
  EXPECT_FALSE(perspective.project({0, 0, -1}, {1, 1, 2}, glm::mat4(1.0f)));
  // In front: x / -z and y / -z of its corners, after the transform moves it 2 m right and 5 m away.
  const std::optional<CoverageGrid::Rect> box = perspective.project({0, 0, -5}, {1, 1, 0}, glm::translate(glm::mat4(1.0f), {2, 0, -5}));
  ASSERT_TRUE(box);
  EXPECT_NEAR(box->min.x, 0.1f, 1e-5f);
  EXPECT_NEAR(box->max.x, 0.3f, 1e-5f);
  EXPECT_NEAR(box->min.y, -0.1f, 1e-5f);
  EXPECT_NEAR(box->max.y, 0.1f, 1e-5f);
}

// Points are projected in blocks (coverage_grid.cpp): a run of them, with a short last block and
// some behind the eye or outside the view, covers the cells each covers alone.
TEST(CoverageGrid, ARunOfPointsCoversWhatEachCoversAlone) {
  const glm::mat4 view_projection = glm::perspective(glm::radians(60.0f), 1.5f, 0.5f, 50.0f);
  CoverageGrid together(view_projection, {48, 32}, 2), one_by_one(view_projection, {48, 32}, 2);
  Random random(7);
  std::vector<glm::vec3> points(21);
  for (glm::vec3& p : points) {
    const float z = -60.0f + 62.0f * random.uniform();  // some behind the eye, some past the far plane
    p = glm::vec3((2.0f * random.uniform() - 1.0f) * std::abs(z), (2.0f * random.uniform() - 1.0f) * std::abs(z), z);
  }
  const glm::mat4 transform = glm::translate(glm::mat4(1.0f), {0.3f, -0.2f, 0.0f});
  together.cover(points, transform);
  for (const glm::vec3& p : points) one_by_one.cover(std::vector<glm::vec3>{p}, transform);
  int covered = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 48; ++x) {
      const CoverageGrid::Rect cell{{-1.0f + x / 24.0f, -1.0f + y / 16.0f}, {-1.0f + (x + 1) / 24.0f, -1.0f + (y + 1) / 16.0f}};
      EXPECT_EQ(together.transmittance(cell), one_by_one.transmittance(cell)) << "cell " << x << ", " << y;
      covered += together.transmittance(cell) == 0.0f;
    }
  }
  EXPECT_GT(covered, 8) << "some of the points are in view";
  EXPECT_LT(covered, 4 * 21) << "and some are not";
}

}  // namespace
}  // namespace pointgen
