// Procedural content: plants, terrain, Poisson placement, ecosystems, crowds. Each property is
// checked against facts the test computes itself.
#include "pointgen/instance_table.hpp"
#include "pointgen/movers/moving_set.hpp"
#include "pointgen/placement/ecosystem.hpp"
#include "pointgen/placement/poisson_disk.hpp"
#include "pointgen/primitives.hpp"
#include "pointgen/table_list.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

namespace pointgen {
namespace {

std::uint64_t fnv(std::uint64_t h, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

template <class T>
std::uint64_t fnv(std::uint64_t h, const std::vector<T>& v) { return fnv(h, v.data(), v.size() * sizeof(T)); }

std::uint64_t hash(const TriangleMesh& m, std::uint64_t h = 14695981039346656037ull) {
  return fnv(fnv(fnv(fnv(h, m.positions), m.normals), m.colors), m.indices);
}

std::uint64_t hash(const Ecosystem& e) {
  std::uint64_t h = 14695981039346656037ull;
  for (const TriangleMesh& m : e.meshes) h = hash(m, h);
  for (const InstanceTable& t : e.tables) h = fnv(fnv(fnv(h, t.transforms), t.tints), t.seeds);
  return h;
}

EcosystemSpec small_ecosystem(std::uint64_t seed) {
  EcosystemSpec spec;
  spec.seed = seed;
  spec.terrain.size = {120.0f, 90.0f};
  spec.terrain.center = {10.0f, -5.0f};
  spec.terrain.relief = 12.0f;
  spec.terrain.feature = 40.0f;
  spec.terrain.resolution = 24;
  spec.terrain.seed = derive_seed(seed, 7);
  for (const auto& [name, count] : std::vector<std::pair<const char*, int>>{
           {"oak", 60}, {"spruce", 50}, {"hazel", 120}, {"meadow grass", 900}, {"poppy", 300}}) {
    PlantRequest request;
    request.species = *find_species(name);
    request.count = count;
    spec.plants.push_back(request);
  }
  spec.clearings.emplace_back(0.0f, 0.0f, 15.0f);
  return spec;
}

// sRGB's transfer (IEC 61966-2-1) in 8-bit steps, written here to check the tints against.
float srgb_steps(float linear) {
  const float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return 255.0f * encoded;
}

TEST(InstanceTable, KeepsATintWithinAQuarterOfAnSRGBStepUpTo1And0Point2PercentTo2) {
  for (int i = 0; i <= 100000; ++i) {
    const float t = static_cast<float>(i) / 100000.0f;
    const glm::vec3 kept = unpack_tint(pack_tint(glm::vec3(t, 1.0f - t, 0.5f * t)));
    EXPECT_NEAR(srgb_steps(kept.r), srgb_steps(t), 0.25f) << t;
    EXPECT_NEAR(srgb_steps(kept.g), srgb_steps(1.0f - t), 0.25f) << 1.0f - t;
    EXPECT_NEAR(srgb_steps(kept.b), srgb_steps(0.5f * t), 0.25f) << 0.5f * t;
    const float above = 1.0f + t;
    EXPECT_NEAR(unpack_tint(pack_tint(glm::vec3(above))).g, above, 0.002f * above) << above;
  }
  const glm::vec3 clamped = unpack_tint(pack_tint(glm::vec3(-1.0f, 3.0f, 2.0f)));
  EXPECT_EQ(clamped.r, 0.0f);
  EXPECT_EQ(clamped.g, 2.0f);
  EXPECT_EQ(clamped.b, 2.0f);
}

TEST(TableList, ReadsTheTablesInPlaceAndAReplacedOneInItsPlace) {
  std::vector<InstanceTable> tables(3);
  for (std::size_t t = 0; t < tables.size(); ++t) {
    tables[t].mesh = t;
    tables[t].add(glm::mat4(1.0f), glm::vec3(1.0f), t);
  }
  TableList list(tables);
  InstanceTable posed{1, {}, {}, {}};
  posed.add(glm::mat4(2.0f), glm::vec3(0.5f), 7);
  posed.add(glm::mat4(3.0f), glm::vec3(0.5f), 8);
  list.replace(1, posed);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(&list[0], &tables[0]) << "a table not replaced is the vector's own, not a copy";
  EXPECT_EQ(&list[2], &tables[2]);
  EXPECT_EQ(list[1].size(), 2u);
  EXPECT_EQ(list[1].seeds[1], 8u);
  EXPECT_EQ(tables[1].size(), 1u) << "the vector's table stays as it was";
  std::vector<const InstanceTable*> visited;
  for (const InstanceTable& table : list) visited.push_back(&table);
  EXPECT_EQ(visited, (std::vector<const InstanceTable*>{&tables[0], &list[1], &tables[2]}));
}

TEST(PlantCatalogue, ShipsThirtyDistinctSpeciesOfSensibleSize) {
  const auto& catalogue = plant_catalogue();
  ASSERT_GE(catalogue.size(), 30u);
  std::set<std::string> names;
  std::set<std::uint64_t> shapes;
  for (const PlantSpecies& s : catalogue) {
    names.insert(s.name);
    const TriangleMesh mesh = build_plant(s, 1);
    EXPECT_GT(mesh.triangle_count(), 50u) << s.name;
    const Bounds b = mesh.bounds();
    EXPECT_GT(b.max.y, 0.6f * s.height) << s.name;
    EXPECT_LT(b.max.y, 1.6f * s.height) << s.name;
    EXPECT_GT(b.min.y, -0.05f * s.height) << s.name << " grows below the ground";
    shapes.insert(hash(mesh));
  }
  EXPECT_EQ(names.size(), catalogue.size());
  EXPECT_EQ(shapes.size(), catalogue.size()) << "two species build the same mesh";
}

TEST(Plants, SameSeedSameMeshOtherSeedOtherMesh) {
  const PlantSpecies& oak = *find_species("oak");
  EXPECT_EQ(hash(build_plant(oak, 5)), hash(build_plant(oak, 5)));
  EXPECT_NE(hash(build_plant(oak, 5)), hash(build_plant(oak, 6)));
}

TEST(Terrain, HeightFollowsTheDrawnTriangles) {
  TerrainSpec spec;
  spec.size = {50.0f, 30.0f};
  spec.resolution = 10;
  spec.relief = 8.0f;
  spec.feature = 20.0f;
  const Terrain terrain(spec);
  const TriangleMesh mesh = terrain.mesh();
  // For random points, find the drawn triangle under them and interpolate its corners.
  Random rng(3);
  for (int k = 0; k < 200; ++k) {
    const glm::vec2 p(rng.uniform(-24.9f, 24.9f), rng.uniform(-14.9f, 14.9f));
    bool found = false;
    for (std::size_t t = 0; t < mesh.indices.size() && !found; t += 3) {
      const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]], c = mesh.positions[mesh.indices[t + 2]];
      const glm::vec2 v0(b.x - a.x, b.z - a.z), v1(c.x - a.x, c.z - a.z), v2(p.x - a.x, p.y - a.z);
      const float d = v0.x * v1.y - v1.x * v0.y;
      const float u = (v2.x * v1.y - v1.x * v2.y) / d, v = (v0.x * v2.y - v2.x * v0.y) / d;
      if (u < -1e-5f || v < -1e-5f || u + v > 1.0f + 1e-5f) continue;
      found = true;
      EXPECT_NEAR(terrain.height(p.x, p.y), a.y + u * (b.y - a.y) + v * (c.y - a.y), 1e-3f);
    }
    EXPECT_TRUE(found);
  }
}

TEST(PoissonDisk, KeepsItsMinimumDistanceAndLeavesNoGaps) {
  Random rng(11);
  const float r = 0.8f;  // 75 × 57 cells of r/√2: tiles of four phases and their edges
  const glm::vec2 size(40.0f, 30.0f);
  const std::vector<glm::vec2> points = poisson_disk({0.0f, 0.0f}, size, r, rng);
  ASSERT_GT(points.size(), 1000u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_TRUE(points[i].x >= 0.0f && points[i].y >= 0.0f && points[i].x < size.x && points[i].y < size.y);
    for (std::size_t j = i + 1; j < points.size(); ++j) ASSERT_GE(glm::distance(points[i], points[j]), r);
  }
  // Filled: a spot farther than r from every point would take one more, so a complete sampling has
  // none; Bridson's method tries a fixed number of candidates, which leaves small gaps (measured
  // up to 1.3 r), never big ones, along the tiles' edges as inside them.
  for (float x = 0.1f; x < size.x; x += 0.2f) {
    for (float y = 0.1f; y < size.y; y += 0.2f) {
      float nearest = 1e9f;
      for (const glm::vec2& p : points) nearest = std::min(nearest, glm::distance(p, {x, y}));
      ASSERT_LE(nearest, 1.5f * r) << x << ", " << y;
    }
  }
}

TEST(PoissonDisk, GivesTheSamePointsOnAnyNumberOfThreads) {
  Random one(5), three(5);
  const std::vector<glm::vec2> a = poisson_disk({-50.0f, -50.0f}, {50.0f, 50.0f}, 0.5f, one, 12, 1);
  const std::vector<glm::vec2> b = poisson_disk({-50.0f, -50.0f}, {50.0f, 50.0f}, 0.5f, three, 12, 3);
  ASSERT_GT(a.size(), 20000u);  // 9 × 9 tiles
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << i;
  EXPECT_EQ(one.next(), three.next());
}

TEST(Ecosystem, SameSeedSameGeometryOtherSeedOtherGeometry) {
  EXPECT_EQ(hash(grow_ecosystem(small_ecosystem(4))), hash(grow_ecosystem(small_ecosystem(4))));
  EXPECT_NE(hash(grow_ecosystem(small_ecosystem(4))), hash(grow_ecosystem(small_ecosystem(5))));
}

// The species (request index) of each instance, from the mesh names "species N".
std::map<std::string, std::vector<glm::mat4>> instances_by_species(const Ecosystem& e) {
  std::map<std::string, std::vector<glm::mat4>> out;
  for (const InstanceTable& t : e.tables) {
    const std::string& name = e.mesh_names[t.mesh];
    if (name == "terrain") continue;
    auto& list = out[name.substr(0, name.rfind(' '))];
    list.insert(list.end(), t.transforms.begin(), t.transforms.end());
  }
  return out;
}

TEST(Ecosystem, CountsMatchTheRequest) {
  const EcosystemSpec spec = small_ecosystem(4);
  const auto by_species = instances_by_species(grow_ecosystem(spec));
  for (const PlantRequest& r : spec.plants) {
    ASSERT_TRUE(by_species.count(r.species.name)) << r.species.name;
    EXPECT_EQ(by_species.at(r.species.name).size(), static_cast<std::size_t>(r.count)) << r.species.name;
  }
}

TEST(Ecosystem, EachLayerKeepsItsMinimumDistanceAndTreesKeepOutOfClearings) {
  const EcosystemSpec spec = small_ecosystem(4);
  const Ecosystem eco = grow_ecosystem(spec);
  const auto by_species = instances_by_species(eco);
  for (int layer = 0; layer < 3; ++layer) {
    std::vector<glm::vec2> points;
    for (const PlantRequest& r : spec.plants) {
      if (placement_layer(r) != layer) continue;
      for (const glm::mat4& m : by_species.at(r.species.name)) points.emplace_back(m[3].x, m[3].z);
    }
    const float radius = eco.layer_radius[static_cast<std::size_t>(layer)];
    // The radius the layer starts from fits its plants; it may shrink a little to make room for
    // the clearing, not collapse.
    const float full = std::sqrt(spec.terrain.size.x * spec.terrain.size.y / (1.6f * static_cast<float>(points.size())));
    ASSERT_GT(radius, 0.6f * full);
    for (std::size_t i = 0; i < points.size(); ++i) {
      for (std::size_t j = i + 1; j < points.size(); ++j) ASSERT_GE(glm::distance(points[i], points[j]), radius * 0.999f);
      if (layer < 2) {
        EXPECT_GE(glm::distance(points[i], glm::vec2(0.0f)), 15.0f) << "a tree or bush in the clearing";
      }
    }
  }
}

// A species from the user's mesh: its mesh as given, one table, its plants among the bushes
// (keeping the bushes' distance from them), each scaled within its range.
TEST(Ecosystem, ASpeciesFromAMeshIsPlacedInItsLayerWithinItsScaleRange) {
  EcosystemSpec spec = small_ecosystem(4);
  PlantRequest cubes;
  cubes.species.name = "cube.obj";
  cubes.count = 40;
  cubes.mesh = std::make_shared<const TriangleMesh>(unit_box());
  cubes.layer = 1;
  cubes.scale = {2.0f, 3.0f};
  spec.plants.push_back(cubes);
  const Ecosystem eco = grow_ecosystem(spec);
  const auto by_species = instances_by_species(eco);
  ASSERT_EQ(by_species.at("cube.obj").size(), 40u);
  const auto mesh = std::find(eco.mesh_names.begin(), eco.mesh_names.end(), "cube.obj") - eco.mesh_names.begin();
  EXPECT_EQ(hash(eco.meshes[static_cast<std::size_t>(mesh)]), hash(unit_box()));
  std::vector<glm::vec2> bushes;
  for (const glm::mat4& m : by_species.at("cube.obj")) {
    const float scale = glm::length(glm::vec3(m[0]));
    EXPECT_GE(scale, 2.0f - 1e-4f);
    EXPECT_LE(scale, 3.0f + 1e-4f);
    bushes.emplace_back(m[3].x, m[3].z);
  }
  for (const glm::mat4& m : by_species.at("hazel")) bushes.emplace_back(m[3].x, m[3].z);
  for (std::size_t i = 0; i < bushes.size(); ++i) {
    for (std::size_t j = i + 1; j < bushes.size(); ++j) ASSERT_GE(glm::distance(bushes[i], bushes[j]), eco.layer_radius[1] * 0.999f);
  }
}

TEST(Ecosystem, PlantsStandOnTheTerrainInsideTheArea) {
  const EcosystemSpec spec = small_ecosystem(9);
  const Ecosystem eco = grow_ecosystem(spec);
  const glm::vec2 min = spec.terrain.center - 0.5f * spec.terrain.size, max = spec.terrain.center + 0.5f * spec.terrain.size;
  std::size_t checked = 0;
  for (const InstanceTable& t : eco.tables) {
    if (eco.mesh_names[t.mesh] == "terrain") continue;
    for (const glm::mat4x3& m : t.transforms) {
      const glm::vec3 p(m[3]);
      EXPECT_NEAR(p.y, eco.terrain.height(p.x, p.z), 1e-4f);
      EXPECT_TRUE(p.x >= min.x && p.x <= max.x && p.z >= min.y && p.z <= max.y);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 1430u);
}

std::vector<glm::vec3> torso_positions(const MovingSet& crowd, double t) {
  std::vector<glm::vec3> out;
  for (const InstanceTable& table : crowd.pose(t, 0)) {
    for (const glm::mat4x3& m : table.transforms) out.emplace_back(m[3]);
  }
  return out;
}

TEST(Crowd, PoseDependsOnTimeAloneAndMoves) {
  const Rect region{{-30.0f, -20.0f}, {30.0f, 20.0f}};
  const std::vector<Rect> avoid = {{{-5.0f, -5.0f}, {5.0f, 5.0f}}};
  const MovingSet a = make_crowd(300, region, avoid, 0.0f, 42);
  const MovingSet b = make_crowd(300, region, avoid, 0.0f, 42);
  EXPECT_EQ(torso_positions(a, 7.25), torso_positions(b, 7.25));
  const std::vector<glm::vec3> now = torso_positions(a, 7.25), later = torso_positions(a, 8.25);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < now.size(); ++i) moved += glm::distance(now[i], later[i]) > 0.3f;
  EXPECT_GT(moved, now.size() * 9 / 10) << "people walk at 0.8 to 1.6 m/s";
}

TEST(Crowd, PeopleWalkInTheirRegionAndAroundObstacles) {
  const Rect region{{-30.0f, -20.0f}, {30.0f, 20.0f}};
  const Rect obstacle{{-5.0f, -5.0f}, {5.0f, 5.0f}};
  const MovingSet crowd = make_crowd(200, region, {obstacle}, 0.0f, 8);
  for (double t = 0.0; t < 60.0; t += 0.5) {
    for (const Mover& m : crowd.movers) {
      const glm::vec3 p = crowd.paths[m.path].position(static_cast<float>(m.speed * t + m.offset));
      ASSERT_TRUE(region.contains({p.x, p.z}));
      ASSERT_FALSE(obstacle.contains({p.x, p.z})) << "a person walked into the obstacle";
    }
  }
}

TEST(Herd, CowsWalkOnTheTerrain) {
  TerrainSpec spec;
  spec.size = {100.0f, 100.0f};
  spec.relief = 15.0f;
  spec.feature = 30.0f;
  const Terrain terrain(spec);
  const MovingSet herd = make_herd(5, terrain, {{-30.0f, -30.0f}, {30.0f, 30.0f}}, 0.0f, 3);
  for (double t : {0.0, 3.3, 100.0}) {
    const std::vector<InstanceTable> tables = herd.pose(t, 0);
    for (const glm::mat4x3& m : tables[0].transforms) EXPECT_NEAR(m[3].y, terrain.height(m[3].x, m[3].z), 1e-4f);
  }
}

}  // namespace
}  // namespace pointgen
