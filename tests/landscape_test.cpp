// A landscape's plants made cell by cell from (seed, cell, site) alone: the hash, the terrain,
// the cells' plants and their rules, and the expected surface of a cell.
#include "pointgen/instance_table.hpp"
#include "pointgen/landscape/growth_rules.hpp"
#include "pointgen/landscape/hash32.hpp"
#include "pointgen/landscape/landscape_cells.hpp"
#include "pointgen/landscape/landscape_pool.hpp"
#include "pointgen/landscape/landscape_terrain.hpp"
#include "pointgen/random.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <optional>
#include <set>
#include <stdexcept>
#include <thread>

namespace pointgen {
namespace {

LandscapeSpecies species(const std::string& name, float weight) {
  LandscapeSpecies s;
  s.name = name;
  s.weight = weight;
  return s;
}

// Two kilometres of hills and a valley, with trees, bushes and ground cover under every kind of
// rule.
LandscapeSpec forest() {
  LandscapeSpec spec;
  spec.seed = 67;
  spec.size = glm::vec2(2000.0f);
  spec.terrain = {.relief = 160.0f, .feature = 640.0f, .octaves = 6, .valley_depth = 60.0f, .valley_width = 400.0f,
                  .valley_meander = 300.0f, .valley_wavelength = 1500.0f};
  LandscapeLayer trees{"trees", 40.0f, 0.004f, {species("oak", 2.0f), species("pine", 1.0f)}};
  trees.species[0].altitude = {-1e9f, 10.0f};
  trees.species[0].grove = 0.5f;
  trees.species[0].grove_size = 200.0f;
  trees.species[1].altitude = {0.0f, 1e9f};
  trees.species[1].slope_max_deg = 20.0f;
  LandscapeLayer bushes{"bushes", 20.0f, 0.02f, {species("hazel", 1.0f)}};
  bushes.species[0].slope_max_deg = 15.0f;
  bushes.species[0].grove = 0.45f;
  LandscapeLayer ground{"ground", 8.0f, 0.5f, {species("grass", 5.0f), species("daisy", 1.0f)}};
  ground.species[1].altitude = {-20.0f, 20.0f};
  ground.species[1].tint_spread = 0.0f;
  spec.layers = {trees, bushes, ground};
  spec.check();
  return spec;
}

// The same layers and species growing everywhere.
LandscapeSpec without_rules(LandscapeSpec spec) {
  for (LandscapeLayer& layer : spec.layers) {
    for (LandscapeSpecies& s : layer.species) s = species(s.name, s.weight);
  }
  return spec;
}

bool same_bytes(const std::vector<LandscapePlant>& a, const std::vector<LandscapePlant>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(LandscapePlant)) == 0;
}

// This thread's processor time: what it computed, whatever else the machine runs.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

glm::vec2 ground_position(const LandscapePlant& plant) { return {plant.transform[3].x, plant.transform[3].z}; }

TEST(LandscapeHash32, IsXxHash32OfTheValuesAsLittleEndianWords) {
  // From libxxhash 0.8.1's XXH32 over the words 1, 0xFFFFFFFF, 7 (first 0 to 3 of them), seed 42.
  static_assert(hash32(0u) == 0x02CC5D05u, "XXH32 of nothing, seed 0");
  EXPECT_EQ(hash32(42u), 0xD5BE6EB8u);
  EXPECT_EQ(hash32(42u, 1), 0xB22F1493u);
  EXPECT_EQ(hash32(42u, 1, -1), 0x385575BDu) << "a signed value hashes as its two's complement bits";
  EXPECT_EQ(hash32(42u, 1u, 0xFFFFFFFFu, 7u), 0xBE575C68u);
  EXPECT_EQ(unit_float(0xFFFFFFFFu), 1.0f - 0x1p-24f);
  EXPECT_EQ(unit_float(0xFFu), 0.0f);
}

TEST(LandscapeCells, ACellIsTheSameBytesAloneAfterOthersShuffledAndOnOneTwoOrFourThreads) {
  const LandscapeSpec spec = forest();
  const CellKey first{2, 101, 37};
  const std::vector<LandscapePlant> alone = generate_cell(spec, first);
  ASSERT_FALSE(alone.empty());

  std::vector<CellKey> keys{first};
  for (int layer = 0; layer < 3; ++layer) {
    for (int i = 0; i < 16; ++i) keys.push_back({layer, (i * 7) % cell_count(spec, layer).x, (i * 13 + layer) % cell_count(spec, layer).y});
  }
  std::vector<std::vector<LandscapePlant>> in_order;
  for (const CellKey& key : keys) in_order.push_back(generate_cell(spec, key));
  EXPECT_TRUE(same_bytes(in_order[0], alone)) << "after itself";
  EXPECT_TRUE(same_bytes(generate_cell(spec, first), alone)) << "after all the others";

  std::vector<std::size_t> shuffled(keys.size());
  for (std::size_t i = 0; i < shuffled.size(); ++i) shuffled[i] = i;
  Random rng(67);
  for (std::size_t i = shuffled.size() - 1; i > 0; --i) std::swap(shuffled[i], shuffled[rng.below(static_cast<std::uint32_t>(i + 1))]);
  for (std::size_t i : shuffled) EXPECT_TRUE(same_bytes(generate_cell(spec, keys[i]), in_order[i])) << "shuffled, key " << i;

  for (std::size_t threads : {1u, 2u, 4u}) {
    std::vector<std::vector<LandscapePlant>> made(keys.size());
    std::vector<std::thread> workers;
    for (std::size_t t = 0; t < threads; ++t) {
      workers.emplace_back([&, t] {
        for (std::size_t i = t; i < keys.size(); i += threads) made[i] = generate_cell(spec, keys[i]);
      });
    }
    for (std::thread& w : workers) w.join();
    for (std::size_t i = 0; i < keys.size(); ++i) EXPECT_TRUE(same_bytes(made[i], in_order[i])) << threads << " threads, key " << i;
  }
}

TEST(LandscapeCells, CountOverAUniformAreaIsDensityTimesAreaWithinFiveBinomialDeviations) {
  LandscapeSpec spec;
  spec.size = glm::vec2(1280.0f);
  spec.layers = {{"uniform", 32.0f, 0.05f, {species("a", 3.0f), species("b", 1.0f)}}};
  const CellSites sites = cell_sites(spec.layers[0]);
  const glm::ivec2 cells = cell_count(spec, 0);
  ASSERT_EQ(cells, glm::ivec2(40));  // no cell reaches past the area
  double count = 0.0, first_species = 0.0;
  for (int z = 0; z < cells.y; ++z) {
    for (int x = 0; x < cells.x; ++x) {
      for (const LandscapePlant& plant : generate_cell(spec, {0, x, z})) {
        count += 1.0;
        first_species += plant.species == 0 ? 1.0 : 0.0;
      }
    }
  }
  const double expected = 0.05 * 1280.0 * 1280.0;
  // Each of the cells' sites is taken with probability p, so the count is binomial.
  const double candidates = static_cast<double>(sites.count()) * cells.x * cells.y;
  const double p = expected / candidates;
  EXPECT_NEAR(count, expected, 5.0 * std::sqrt(candidates * p * (1.0 - p)));
  // Each plant is the first species with probability 3/4.
  EXPECT_NEAR(first_species, 0.75 * count, 5.0 * std::sqrt(count * 0.75 * 0.25));
}

// 1270 m is 39 cells and 22 m of a 40th: the last cells' sites past the edge grow nothing, so the
// count is still density × area, a sum of independent sites with a variance below its mean.
TEST(LandscapeCells, NoPlantGrowsPastTheEdgeThatCutsTheLastCells) {
  LandscapeSpec spec;
  spec.size = glm::vec2(1270.0f);
  spec.layers = {{"uniform", 32.0f, 0.05f, {species("a", 1.0f)}}};
  const glm::ivec2 cells = cell_count(spec, 0);
  ASSERT_EQ(cells, glm::ivec2(40));
  double count = 0.0;
  for (int z = 0; z < cells.y; ++z) {
    for (int x = 0; x < cells.x; ++x) {
      for (const LandscapePlant& plant : generate_cell(spec, {0, x, z})) {
        EXPECT_TRUE(glm::all(glm::lessThanEqual(glm::abs(ground_position(plant)), 0.5f * spec.size))) << "cell " << x << ", " << z;
        count += 1.0;
      }
    }
  }
  const double expected = 0.05 * 1270.0 * 1270.0;
  EXPECT_NEAR(count, expected, 5.0 * std::sqrt(expected));
}

TEST(LandscapeCells, EveryPlantGrowsWithinItsSpeciesAltitudeSlopeGroveScaleAndTintRules) {
  const LandscapeSpec spec = forest();
  const LandscapeSpec unruled = without_rules(spec);
  const LandscapeTerrain terrain(spec.terrain, spec.seed);
  for (int layer = 0; layer < 3; ++layer) {
    const LandscapeLayer& l = spec.layers[static_cast<std::size_t>(layer)];
    const glm::ivec2 cells = cell_count(spec, layer);
    std::size_t plants = 0, unruled_plants = 0;
    for (int z = 0; z < cells.y; z += std::max(1, cells.y / 12)) {
      for (int x = 0; x < cells.x; x += std::max(1, cells.x / 12)) {
        unruled_plants += generate_cell(unruled, {layer, x, z}).size();
        for (const LandscapePlant& plant : generate_cell(spec, {layer, x, z})) {
          ++plants;
          const LandscapeSpecies& s = l.species[plant.species];
          const glm::vec2 p = ground_position(plant);
          const float height = terrain.height(p.x, p.y);
          EXPECT_EQ(plant.transform[3].y, height) << "stands on the ground";
          EXPECT_GE(height, s.altitude.x) << s.name;
          EXPECT_LE(height, s.altitude.y) << s.name;
          const float slope_deg = glm::degrees(std::acos(terrain.normal(p.x, p.y).y));
          EXPECT_LE(slope_deg, s.slope_max_deg + 1e-3f) << s.name;
          EXPECT_GE(grove_noise(spec, layer, static_cast<int>(plant.species), p), s.grove) << s.name;
          const float scale = uniform_scale(glm::mat4(plant.transform));
          EXPECT_GE(scale, s.scale.x * (1.0f - 1e-5f)) << s.name;
          EXPECT_LE(scale, s.scale.y * (1.0f + 1e-5f)) << s.name;
          EXPECT_TRUE(plant.transform[1].x == 0.0f && plant.transform[1].z == 0.0f) << "upright";
          EXPECT_NEAR(plant.transform[1].y, scale, 1e-5f * scale) << "scaled alike on every axis";
          // Within the spread, and a quarter of an sRGB step (pack_tint's) of it.
          const glm::vec3 tint = unpack_tint(plant.tint);
          EXPECT_TRUE(glm::all(glm::lessThanEqual(glm::abs(tint - 1.0f), glm::vec3(s.tint_spread + 0.002f)))) << s.name;
        }
      }
    }
    EXPECT_GT(plants, 100u) << l.name;
    EXPECT_GT(unruled_plants, plants) << l.name << ": the rules keep some plants out";
  }
}

// Inside, and spread over all of it: where plants grow everywhere, their mean offset from their
// cells' centres is 0 within five deviations of a uniform spread (a cell's side / sqrt(12 n)).
// Moss's cells of 7.3 m (no float's multiple) are where rounding 50 km out could carry plants
// past their cell.
TEST(LandscapeCells, PlantsSpreadOverTheirCellAndStayInsideItEvenFiftyKilometresOut) {
  LandscapeSpec near = without_rules(forest());
  near.layers.push_back({"moss", 7.3f, 2.0f, {species("moss", 1.0f)}});
  LandscapeSpec wide = near;
  wide.size = glm::vec2(LandscapeSpec::max_size);
  for (const LandscapeSpec& spec : {near, wide}) {
    for (int layer = 0; layer < 4; ++layer) {
      const glm::ivec2 cells = cell_count(spec, layer);
      glm::dvec2 offsets(0.0);
      std::size_t plants = 0;
      for (const glm::ivec2 block : {glm::ivec2(0), cells / 3, cells - 16}) {
        for (int k = 0; k < 256; ++k) {
          const CellKey key{layer, block.x + k % 16, block.y + k / 16};
          const CellBounds bounds = cell_bounds(spec, key);
          for (const LandscapePlant& plant : generate_cell(spec, key)) {
            const glm::vec2 p = ground_position(plant);
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, bounds.min)) && glm::all(glm::lessThanEqual(p, bounds.max)))
                << "layer " << layer << " cell " << key.x << ", " << key.z;
            offsets += glm::dvec2((p - 0.5f * (bounds.min + bounds.max)) / (bounds.max - bounds.min));
            ++plants;
          }
        }
      }
      ASSERT_GT(plants, 100u);
      const double deviation = std::sqrt(1.0 / (12.0 * static_cast<double>(plants)));
      EXPECT_NEAR(offsets.x / static_cast<double>(plants), 0.0, 5.0 * deviation) << "layer " << layer << " of " << spec.size.x << " m";
      EXPECT_NEAR(offsets.y / static_cast<double>(plants), 0.0, 5.0 * deviation) << "layer " << layer << " of " << spec.size.x << " m";
    }
  }
}

// Value noise may break where its lattice lines are (each octave's at multiples of feature /
// 2^octave, the valley's along x at multiples of its wavelength); cells' borders are where
// neighbouring cells' plants meet. Across each, the height steps no more than the slope on
// either side gives.
TEST(LandscapeTerrain, HeightsAgreeAcrossLatticeLinesAndCellBorders) {
  const LandscapeSpec spec = forest();
  const LandscapeTerrain terrain(spec.terrain, spec.seed);
  std::vector<float> borders;
  const float finest = spec.terrain.feature / static_cast<float>(1 << (spec.terrain.octaves - 1));
  for (int k = -40; k <= 40; k += 3) borders.push_back(finest * static_cast<float>(k));
  for (int k = -1; k <= 1; ++k) borders.push_back(spec.terrain.valley_wavelength * static_cast<float>(k));
  for (const LandscapeLayer& layer : spec.layers) {
    for (int k = 0; k < 5; ++k) borders.push_back(cell_bounds(spec, {static_cast<int>(&layer - spec.layers.data()), 7 * k, 0}).min.x);
  }
  constexpr float step = 0.01f;
  auto step_across = [&](float b, float along, bool across_x, float from, float to) {
    return std::abs(across_x ? terrain.height(b + to, along) - terrain.height(b + from, along)
                             : terrain.height(along, b + to) - terrain.height(along, b + from));
  };
  for (float b : borders) {
    for (float along = -900.0f; along <= 900.0f; along += 37.0f) {
      for (bool across_x : {true, false}) {
        const float jump = step_across(b, along, across_x, -step, step);
        const float sides = std::max(step_across(b, along, across_x, step, 3.0f * step), step_across(b, along, across_x, -3.0f * step, -step));
        EXPECT_LE(jump, 2.0f * sides + 1e-3f) << "across " << (across_x ? "x = " : "z = ") << b << " at " << along;
      }
    }
  }
}

TEST(LandscapeCells, MakesACellAtTheFarCornerOfA100KmLandscapeAloneAndAtOnce) {
  LandscapeSpec spec = forest();
  spec.size = glm::vec2(LandscapeSpec::max_size);
  const int ground = 2;
  const glm::ivec2 cells = cell_count(spec, ground);
  ASSERT_EQ(cells, glm::ivec2(12500)) << "156 million cells of ground cover";
  const CellKey corner{ground, cells.x - 1, cells.y - 1};
  const double start = thread_seconds();
  const std::vector<LandscapePlant> plants = generate_cell(spec, corner);
  // Its 36 sites take microseconds; making first the cells before it in its row takes some 60 ms,
  // all cells before it hours. The bound leaves room for a machine busy with other work.
  EXPECT_LT(thread_seconds() - start, 0.02);
  EXPECT_FALSE(plants.empty());
  EXPECT_LE(plants.capacity(), static_cast<std::size_t>(cell_sites(spec.layers[ground]).count())) << "room for its own sites only";
  EXPECT_EQ(cell_bounds(spec, corner).max, 0.5f * spec.size);
  EXPECT_TRUE(generate_cell(spec, {ground, cells.x, 0}).empty()) << "past the edge";
}

// Checked against every cell of the layer: those reaching within the radius (their nearest point
// to the centre), and no other.
TEST(LandscapeCells, CellsWithinARadiusAreThoseReachingIntoIt) {
  const LandscapeSpec spec = forest();
  for (const glm::vec3 disc : {glm::vec3(130.0f, -410.0f, 95.0f), glm::vec3(-990.0f, 990.0f, 60.0f), glm::vec3(3000.0f, 0.0f, 100.0f)}) {
    const glm::vec2 center(disc.x, disc.y);
    std::vector<CellKey> reaching;
    const glm::ivec2 cells = cell_count(spec, 0);
    for (int z = 0; z < cells.y; ++z) {
      for (int x = 0; x < cells.x; ++x) {
        const CellBounds b = cell_bounds(spec, {0, x, z});
        const glm::vec2 nearest = glm::clamp(center, b.min, b.max);
        if (glm::length(nearest - center) <= disc.z) reaching.push_back({0, x, z});
      }
    }
    EXPECT_EQ(cells_within(spec, 0, center, disc.z), reaching) << center.x << ", " << center.y;
  }
}

TEST(LandscapeCells, ExpectedSurfaceIsTheMeanOfTheSurfaceMade) {
  LandscapeSpec spec;
  spec.size = glm::vec2(640.0f);
  spec.layers = {{"uniform", 32.0f, 0.05f, {species("a", 3.0f), species("b", 1.0f), species("nowhere", 1.0f)}}};
  spec.layers[0].species[0].surface = 2.0f;
  spec.layers[0].species[0].scale = {0.5f, 1.5f};
  spec.layers[0].species[1].surface = 10.0f;
  spec.layers[0].species[2].altitude = {1e6f, 1e7f};  // above every hill
  // Mean squared scale over a uniform [a, b]: (a² + ab + b²) / 3.
  const float per_plant = 0.6f * 2.0f * (0.25f + 0.75f + 2.25f) / 3.0f + 0.2f * 10.0f * (0.5625f + 0.9375f + 1.5625f) / 3.0f;
  const glm::ivec2 cells = cell_count(spec, 0);
  double expected = 0.0, made = 0.0, made_squares = 0.0;
  for (int z = 0; z < cells.y; ++z) {
    for (int x = 0; x < cells.x; ++x) {
      const float cell = expected_surface(spec, {0, x, z});
      EXPECT_NEAR(cell, 0.05f * 32.0f * 32.0f * per_plant, 1e-4f * cell);
      expected += cell;
      for (const LandscapePlant& plant : generate_cell(spec, {0, x, z})) {
        ASSERT_NE(plant.species, 2u) << "grows nowhere";
        const float scale = uniform_scale(glm::mat4(plant.transform));
        const double surface = spec.layers[0].species[plant.species].surface * scale * scale;
        made += surface;
        made_squares += surface * surface;
      }
    }
  }
  // Each site adds a surface or nothing: five deviations of the sum of independent sites.
  const double sites = static_cast<double>(cell_sites(spec.layers[0]).count()) * cells.x * cells.y;
  const double variance = made_squares / sites - (made / sites) * (made / sites);
  EXPECT_NEAR(made, expected, 5.0 * std::sqrt(sites * variance));
}

// The count the whole landscape stands for, probed, against every plant of its trees and bushes
// made (46,510): within 2 %, four times the binomial spread of that many. The rules keep about
// half the sites, so a count that ignored them would be off by far more.
TEST(LandscapeCells, ExpectedPlantCountIsTheCountOfEveryCellMade) {
  LandscapeSpec spec = forest();
  spec.layers.pop_back();  // ground cover: 2 million plants, slow to make here
  double made = 0.0;
  for (int layer = 0; layer < static_cast<int>(spec.layers.size()); ++layer) {
    const glm::ivec2 cells = cell_count(spec, layer);
    for (int z = 0; z < cells.y; ++z) {
      for (int x = 0; x < cells.x; ++x) made += static_cast<double>(generate_cell(spec, {layer, x, z}).size());
    }
  }
  EXPECT_NEAR(expected_plant_count(spec), made, 0.02 * made);
}

// The pool's reach per layer of the forest: trees to 200 m, bushes to 120, ground cover to 40.
const std::vector<float> forest_reach{200.0f, 120.0f, 40.0f};
const std::vector<std::size_t> forest_meshes{10, 11, 12, 13, 14};

struct NearCell {
  float distance;
  CellKey key;
  auto operator<=>(const NearCell&) const = default;
};

// What a pool of `capacity` plants should hold for `eye`, from the cells and nothing else: every
// layer's cells within reach, nearest first, until the next would not fit; then per species its
// plants cell by cell in key order.
std::vector<InstanceTable> expected_pool(const LandscapeSpec& spec, glm::vec2 eye, std::size_t capacity) {
  std::vector<NearCell> near;
  for (int layer = 0; layer < 3; ++layer) {
    const glm::ivec2 cells = cell_count(spec, layer);
    for (int z = 0; z < cells.y; ++z) {
      for (int x = 0; x < cells.x; ++x) {
        const CellBounds b = cell_bounds(spec, {layer, x, z});
        const float d = glm::length(glm::clamp(eye, b.min, b.max) - eye);
        if (d <= forest_reach[static_cast<std::size_t>(layer)]) near.push_back({d, {layer, x, z}});
      }
    }
  }
  std::sort(near.begin(), near.end());
  std::vector<CellKey> chosen;
  std::size_t plants = 0;
  for (const NearCell& cell : near) {
    plants += generate_cell(spec, cell.key).size();
    if (plants > capacity) break;
    chosen.push_back(cell.key);
  }
  std::sort(chosen.begin(), chosen.end());
  std::vector<InstanceTable> tables;
  for (std::size_t mesh : forest_meshes) tables.push_back({mesh, {}, {}, {}});
  for (std::size_t mesh : forest_meshes) tables.push_back({mesh, {}, {}, {}, true});  // no far blocks
  const std::size_t first_species[] = {0, 2, 3};
  for (const CellKey& key : chosen) {
    for (const LandscapePlant& plant : generate_cell(spec, key)) {
      InstanceTable& table = tables[first_species[key.layer] + plant.species];
      table.transforms.push_back(plant.transform);
      table.tints.push_back(plant.tint);
      table.seeds.push_back(plant.seed);
    }
  }
  return tables;
}

// An eye at (x, z) on the ground asking no far blocks.
LandscapeView near_only(glm::vec2 eye) { return {{eye.x, 0.0f, eye.y}, glm::mat4(1.0f), 0.0f}; }

void expect_same_tables(const std::vector<InstanceTable>& a, const std::vector<InstanceTable>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t t = 0; t < a.size(); ++t) {
    EXPECT_EQ(a[t].mesh, b[t].mesh);
    EXPECT_EQ(a[t].rounds_up, b[t].rounds_up);
    ASSERT_EQ(a[t].size(), b[t].size()) << "table " << t;
    EXPECT_EQ(std::memcmp(a[t].transforms.data(), b[t].transforms.data(), a[t].size() * sizeof(glm::mat4x3)), 0) << "table " << t;
    EXPECT_EQ(a[t].tints, b[t].tints) << "table " << t;
    EXPECT_EQ(a[t].seeds, b[t].seeds) << "table " << t;
  }
}

TEST(LandscapePool, HoldsTheCellsWithinReachWhateverItHeldBefore) {
  const LandscapeSpec spec = forest();
  const std::size_t capacity = LandscapePool::most_plants_in_reach(spec, forest_reach);
  const glm::vec2 eye(130.0f, -410.0f);
  const std::vector<InstanceTable> expected = expected_pool(spec, eye, capacity);
  std::size_t plants = 0;
  for (const InstanceTable& table : expected) plants += table.size();
  ASSERT_GT(plants, 1000u);
  LandscapePool fresh(spec, forest_reach, forest_meshes, capacity);
  EXPECT_TRUE(fresh.fill(near_only(eye)));
  EXPECT_EQ(fresh.stats().cells_left_out, 0u) << "a pool as large as the reach's sites leaves none out";
  EXPECT_EQ(fresh.stats().plants, plants);
  EXPECT_EQ(fresh.stats().plants_made, plants);
  expect_same_tables(fresh.tables(), expected);
  // Flown from elsewhere, past the edge and through cells it shares with this eye.
  LandscapePool flown(spec, forest_reach, forest_meshes, capacity);
  for (const glm::vec2 before : {glm::vec2(-990.0f, 990.0f), glm::vec2(3000.0f, 0.0f), glm::vec2(100.0f, -380.0f)}) flown.fill(near_only(before));
  EXPECT_TRUE(flown.fill(near_only(eye)));
  EXPECT_LT(flown.stats().plants_made, plants) << "cells kept from the eye before are not made again";
  expect_same_tables(flown.tables(), expected);
  EXPECT_FALSE(flown.fill(near_only(eye))) << "the same eye again changes nothing";
  EXPECT_EQ(flown.stats().cells_made, 0u);
}

TEST(LandscapePool, AFullPoolHoldsTheNearestCellsThatFitAndNoMorePlants) {
  const LandscapeSpec spec = forest();
  const glm::vec2 eye(-200.0f, 300.0f);
  LandscapePool all(spec, forest_reach, forest_meshes, LandscapePool::most_plants_in_reach(spec, forest_reach));
  all.fill(near_only(eye));
  const std::size_t capacity = all.stats().plants / 3;
  LandscapePool pool(spec, forest_reach, forest_meshes, capacity);
  pool.fill(near_only(eye));
  EXPECT_LE(pool.stats().plants, capacity);
  EXPECT_GT(pool.stats().cells_left_out, 0u);
  EXPECT_EQ(pool.stats().cells + pool.stats().cells_left_out, all.stats().cells);
  expect_same_tables(pool.tables(), expected_pool(spec, eye, capacity));
}

// A flight of 2 km over the forest, and the same reach over landscapes of 2, 20 and 100 km: the
// cells kept made never pass twice the pool, which the reach sets, not the area.
TEST(LandscapePool, MemoryIsSetByTheReachNotByTheArea) {
  std::optional<std::size_t> capacity;
  for (const float size : {2000.0f, 20000.0f, 100000.0f}) {
    LandscapeSpec spec = forest();
    spec.size = glm::vec2(size);
    const std::size_t most = LandscapePool::most_plants_in_reach(spec, forest_reach);
    if (capacity) {
      EXPECT_EQ(most, *capacity) << size;
    }
    capacity = most;
    LandscapePool pool(spec, forest_reach, forest_meshes, most / 2);
    std::size_t most_kept = 0;
    for (int step = 0; step <= 40; ++step) {
      pool.fill(near_only({-900.0f + 45.0f * static_cast<float>(step), 20.0f * std::sin(0.3f * static_cast<float>(step))}));
      EXPECT_LE(pool.stats().plants, most / 2);
      most_kept = std::max(most_kept, pool.stats().plants_kept);
    }
    EXPECT_LE(most_kept, most) << size;
    EXPECT_GT(most_kept, most / 4) << size << ": the flight kept cells";
  }
}

// The forest's trees alone, seen from 30 m above its middle looking north over it at 960 × 540
// with k = 2.5: far blocks from 200 m out.
struct FarView {
  LandscapeSpec spec = [] {
    LandscapeSpec s = forest();
    s.layers.resize(1);
    return s;
  }();
  const std::vector<float> reach{200.0f};
  const std::vector<std::size_t> meshes{10, 11};
  LandscapeView view = [] {
    const glm::vec3 eye(0.0f, 30.0f, 400.0f);
    const float pixels_per_radian = 270.0f / std::tan(glm::radians(30.0f));
    return LandscapeView{eye, glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 1.0f, 5000.0f) * glm::lookAt(eye, glm::vec3(0.0f, 0.0f, -600.0f), glm::vec3(0, 1, 0)),
                         0.5f * 2.5f * pixels_per_radian * pixels_per_radian};
  }();
};

// The blocks and the cells made whole share no ground; a block is a single cell or at most a
// quarter of its distance across; and every cell beyond the reach inside the view's frustum
// belongs to a block (where every block has candidates: at a far higher density of points).
TEST(LandscapePool, FarBlocksAndNearCellsShareNoGroundAndCoverTheViewBeyondTheReach) {
  FarView f;
  f.view.points_at_a_metre *= 1e6f;
  LandscapePool pool(f.spec, f.reach, f.meshes, 1u << 24);
  pool.fill(f.view);
  ASSERT_GT(pool.blocks().size(), 10u);
  EXPECT_EQ(pool.stats().cells_left_out, 0u);
  const glm::vec2 eye(f.view.eye.x, f.view.eye.z);
  std::set<std::pair<int, int>> covered;
  for (const LandscapePool::Block& block : pool.blocks()) {
    const CellBounds b = far_block_bounds(f.spec, block.key);
    const float near = glm::distance(glm::clamp(eye, b.min, b.max), eye);
    EXPECT_GT(near, 200.0f) << "beyond the reach";
    if (block.key.level > 0) {
      EXPECT_LE(std::max(b.max.x - b.min.x, b.max.y - b.min.y), 0.25f * near + 1e-3f);
    }
    const int cells = 1 << block.key.level;
    for (int z = block.key.z * cells; z < (block.key.z + 1) * cells; ++z) {
      for (int x = block.key.x * cells; x < (block.key.x + 1) * cells; ++x) {
        EXPECT_TRUE(covered.insert({x, z}).second) << "cell " << x << ", " << z << " in two blocks";
      }
    }
  }
  const glm::ivec2 count = cell_count(f.spec, 0);
  std::size_t in_view = 0;
  for (int z = 0; z < count.y; ++z) {
    for (int x = 0; x < count.x; ++x) {
      const CellBounds b = cell_bounds(f.spec, {0, x, z});
      if (glm::distance(glm::clamp(eye, b.min, b.max), eye) <= 200.0f) continue;
      // In view where its middle at ground level projects inside the frame, well in front.
      const glm::vec2 middle = 0.5f * (b.min + b.max);
      const glm::vec4 clip = f.view.view_projection * glm::vec4(middle.x, 0.0f, middle.y, 1.0f);
      if (clip.w <= 0.0f || glm::any(glm::greaterThan(glm::abs(glm::vec2(clip) / clip.w), glm::vec2(0.9f)))) continue;
      ++in_view;
      EXPECT_TRUE(covered.count({x, z})) << "cell " << x << ", " << z;
    }
  }
  EXPECT_GT(in_view, 20u);
}

// What the pool draws against the points every plant of its cells would ask, each by the density
// formula at its own distance and surface: the cells made whole, the band's thinned and the far
// blocks' candidates together ask the same within a fifth, though the blocks count from their
// centres, round to a quarter octave and pick their own sites.
TEST(LandscapePool, ItDrawsAboutThePointsItsCellsPlantsWouldAsk) {
  const FarView f;
  LandscapePool pool(f.spec, f.reach, f.meshes, 1u << 24);
  pool.fill(f.view);
  const auto points = [&](const glm::mat4x3& transform, std::size_t species) {
    const float scale = uniform_scale(glm::mat4(transform));
    const float d = glm::distance(f.view.eye, transform[3]);
    return f.view.points_at_a_metre * f.spec.layers[0].species[species].surface * scale * scale / (d * d);
  };
  std::set<std::pair<int, int>> cells;
  for (const CellKey& key : cells_within(f.spec, 0, {f.view.eye.x, f.view.eye.z}, (1.0f + LandscapePool::band) * 200.0f)) cells.insert({key.x, key.z});
  for (const LandscapePool::Block& block : pool.blocks()) {
    const int side = 1 << block.key.level;
    for (int z = block.key.z * side; z < (block.key.z + 1) * side; ++z) {
      for (int x = block.key.x * side; x < (block.key.x + 1) * side; ++x) cells.insert({x, z});
    }
  }
  double asked = 0.0;
  for (const auto& [x, z] : cells) {
    for (const LandscapePlant& plant : generate_cell(f.spec, {0, x, z})) asked += points(plant.transform, plant.species);
  }
  ASSERT_GT(asked, 1000.0);
  // Each plant draws what the formula asks of it; a far block's candidate, rounding up, a point.
  const std::vector<InstanceTable> tables = pool.tables();
  EXPECT_TRUE(tables[2].rounds_up && tables[3].rounds_up);
  EXPECT_EQ(tables[2].size() + tables[3].size(), pool.stats().far_plants);
  double drawn = 0.0;
  for (std::size_t t = 0; t < 4; ++t) {
    for (std::size_t i = 0; i < tables[t].size(); ++i) {
      const float p = points(tables[t].transforms[i], t % 2);
      drawn += tables[t].rounds_up ? std::floor(p + InstanceTable::round_up_threshold) : p;
    }
  }
  EXPECT_NEAR(drawn, asked, 0.2 * asked) << pool.blocks().size() << " blocks, " << pool.stats().far_plants << " far plants";
}

// Within the reach a cell's plants are all kept, a quarter beyond it none, and between they thin
// out with the cell's distance (by eighths, each plant by its own hash) while its far block takes
// the rest: plants give way to candidates a few at a time as the eye moves, not a cell at once.
TEST(LandscapePool, AcrossTheBandACellKeepsItsPlantsInProportionToItsDistance) {
  FarView f;
  f.spec.layers[0].density = 0.02f;  // five times the forest's trees: some hundreds in the band
  LandscapePool pool(f.spec, f.reach, f.meshes, 1u << 24);
  pool.fill(f.view);
  const std::vector<InstanceTable> tables = pool.tables();
  std::set<std::uint32_t> held;
  for (std::size_t t = 0; t < 2; ++t) held.insert(tables[t].seeds.begin(), tables[t].seeds.end());
  const glm::vec2 eye(f.view.eye.x, f.view.eye.z);
  double band_plants = 0.0, band_kept = 0.0, band_expected = 0.0;
  for (const CellKey& key : cells_within(f.spec, 0, eye, 260.0f)) {
    const CellBounds b = cell_bounds(f.spec, key);
    const float d = glm::distance(glm::clamp(eye, b.min, b.max), eye);
    const std::vector<LandscapePlant> plants = generate_cell(f.spec, key);
    const auto kept = std::count_if(plants.begin(), plants.end(), [&](const LandscapePlant& p) { return held.count(p.seed) > 0; });
    if (d <= 200.0f) {
      EXPECT_EQ(kept, static_cast<long>(plants.size())) << "within reach";
    } else if (d >= 250.0f) {
      EXPECT_EQ(kept, 0) << "past the band";
    } else {
      band_plants += static_cast<double>(plants.size());
      band_kept += static_cast<double>(kept);
      band_expected += static_cast<double>(plants.size()) * (250.0 - d) / 50.0;
    }
  }
  ASSERT_GT(band_plants, 100.0);
  EXPECT_NEAR(band_kept, band_expected, 0.1 * band_expected + 3.0 * std::sqrt(band_expected));
  EXPECT_GT(band_kept, 0.2 * band_plants);
  EXPECT_LT(band_kept, 0.8 * band_plants);
}

TEST(LandscapeSpec, CheckNamesTheFirstFieldOutOfRange) {
  LandscapeSpec spec = forest();
  spec.layers[1].species[0].scale = {2.0f, 1.0f};
  try {
    spec.check();
    FAIL() << "a reversed scale range passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("layers[1].species[0].scale:", 0), 0u) << e.what();
  }
  spec = forest();
  spec.size.x = 2.0f * LandscapeSpec::max_size;
  EXPECT_THROW(spec.check(), std::invalid_argument);
}

}  // namespace
}  // namespace pointgen
