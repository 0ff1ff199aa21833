// The GPU sampler against the CPU sampler (its oracle) without occlusion: the same plants culled,
// the same counts, the same choice of points or polygons, and a draw list a point splat can read.
#include "app/gl/context.hpp"
#include "depth_coverage.hpp"
#include "test_support.hpp"
#include "app/render/depth_pyramid.hpp"
#include "app/render/drawn_commands.hpp"
#include "app/render/gpu_sampler.hpp"
#include "app/render/renderer.hpp"
#include "app/render/silhouette_pass.hpp"
#include "app/scene/scene_file.hpp"
#include "pointgen/random.hpp"
#include "pointgen/sampling/screen_rect.hpp"

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <utility>

namespace ecoview {
namespace {

// Plants of two species on a grid from 5 m to 400 m ahead and to the sides, some behind the
// camera: near ones polygons, middle ones in the band, far ones a few points or none.
// With `wall`, a box 20 m ahead hides every plant beyond it in the middle of the view.
std::string plantation(bool wall = false) {
  std::ostringstream s;
  s << R"({"camera": {"position": [0, 3, 0], "target": [0, 2, -60], "fov_y_deg": 50, "near": 0.5, "far": 1000},
          "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}], "objects": [)";
  if (wall) s << R"({"type": "box", "min": [-12, 0, -21], "max": [12, 40, -20]}, )";
  const char* species[] = {"beech", "fern"};
  for (int k = 0; k < 2; ++k) {
    s << (k ? ", " : "") << R"({"type": "plant", "species": ")" << species[k] << R"(", "positions": [)";
    bool first = true;
    for (int z = -400; z <= 40; z += 8 + 5 * k) {
      for (int x = -200; x <= 200; x += 12 + 7 * k) {
        s << (first ? "" : ", ") << "[" << x + 3 * k << ", 0, " << z << "]";
        first = false;
      }
    }
    s << "]}";
  }
  s << "]}";
  return s.str();
}

struct Choice {
  std::uint32_t points = 0;
  bool polygons = false;
};

class GpuSampling : public testing::Test {
 protected:
  std::unique_ptr<GlContext> context = create_headless_context("egl");
  Scene scene = load_scene({"plantation.json", plantation(), [](const std::string&) { return std::nullopt; }});
  RenderSettings settings = [] {
    RenderSettings s;
    s.width = 960;
    s.height = 540;
    return s;
  }();
  PointSamples samples{scene, settings.points_per_triangle, true};

  // A frame of the scene `json` with `settings`: its pixels in shadow and its figures.
  struct Shadowed {
    std::size_t shadowed = 0;
    FrameStats stats;
  };
  Shadowed render_shadows(const std::string& json) const {
    const Scene s = load_scene({"scene.json", json, [](const std::string&) { return std::nullopt; }});
    Renderer renderer(s, settings);
    renderer.render(s.camera, s.lights[0]);
    const Image8 visibility = renderer.frame().read_visibility();
    return {static_cast<std::size_t>(std::count_if(visibility.samples.begin(), visibility.samples.end(), [](std::uint8_t v) { return v < 128; })),
            renderer.stats()};
  }

  // A frame of `json` with the paged map, the pages' tiles it drew, and the same frame with the
  // volumes, whose exact shadows it is held to.
  struct PagedAndExact {
    Shadowed paged;
    std::size_t tiles = 0;
    Shadowed exact;
  };
  PagedAndExact render_paged_and_exact(const std::string& json) {
    settings.method = shadow::Method::adaptive;
    const Shadowed paged = render_shadows(json);
    settings.method = shadow::Method::volumes;
    return {paged, static_cast<std::size_t>(paged.stats.pages.tiles), render_shadows(json)};
  }

  pointgen::SamplerView view() const {
    const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
    pointgen::SamplerView v = sampler_view(scene.camera, settings, {scene.camera.projection(aspect) * scene.camera.view()});
    v.occlusion = false;
    return v;
  }
};

TEST_F(GpuSampling, ChoosesAsTheCpuSamplerDoesWithoutOcclusion) {
  const pointgen::SampledFrame cpu = pointgen::sample_view(view(), scene.groups, samples.meshes());
  std::map<std::pair<std::uint32_t, std::uint32_t>, Choice> oracle;
  for (const pointgen::PointDraw& d : cpu.points) {
    ASSERT_EQ(d.first, 0u) << "a cell counted as one: the plantation is meant to have none";
    oracle[{d.table, d.instance}].points += d.count;
  }
  for (std::uint32_t t = 0; t < cpu.polygons.size(); ++t) {
    for (std::uint32_t i : cpu.polygons[t]) oracle[{t, i}].polygons = true;
  }
  ASSERT_GT(cpu.point_count, 100000u);
  ASSERT_GT(cpu.triangle_count, 0u);

  GpuSampler gpu(scene.groups, samples, GpuScene(scene).point_mesh_places());
  gpu.sample(view());
  const std::vector<GpuSampler::Count> counts = gpu.read_counts();
  ASSERT_EQ(counts.size(), scene.groups[0].size() + scene.groups[1].size());
  // Float rounding may put a count one point over or under its rounding threshold, and a plant
  // at a band edge on its other side: at most one plant in a thousand.
  std::size_t plants = 0, other_choice = 0, other_count = 0;
  std::uint64_t gpu_points = 0;
  for (std::uint32_t t = 0; t < scene.groups.size(); ++t) {
    for (std::uint32_t i = 0; i < scene.groups[t].size(); ++i) {
      const GpuSampler::Count c = counts[gpu.first_plant(t) + i];
      const auto found = oracle.find({t, i});
      const Choice expected = found == oracle.end() ? Choice{} : found->second;
      ++plants;
      gpu_points += c.points;
      other_choice += c.polygons != expected.polygons;
      other_count += c.points + 1 < expected.points || c.points > expected.points + 1;
    }
  }
  EXPECT_LE(other_choice, plants / 1000) << other_choice << " of " << plants;
  EXPECT_LE(other_count, plants / 1000) << other_count << " of " << plants;
  EXPECT_NEAR(static_cast<double>(gpu_points), static_cast<double>(cpu.point_count), 0.002 * static_cast<double>(cpu.point_count));
}

TEST_F(GpuSampling, WritesTheDrawsInPlantOrderWithoutGaps) {
  GpuSampler gpu(scene.groups, samples, GpuScene(scene).point_mesh_places());
  gpu.sample(view());
  const std::vector<GpuSampler::Count> counts = gpu.read_counts();
  const std::vector<glm::uvec4> draws = gpu.read_draws();
  ASSERT_FALSE(draws.empty());
  std::size_t next = 0;
  std::uint32_t first_point = 0;
  for (std::uint32_t plant = 0; plant < counts.size(); ++plant) {
    if (counts[plant].points == 0) continue;
    ASSERT_LT(next, draws.size());
    const glm::uvec4 d = draws[next++];
    EXPECT_EQ(d.x, first_point);
    EXPECT_EQ(d.y, counts[plant].points);
    EXPECT_EQ(d.w, plant);
    const std::size_t table = plant < gpu.first_plant(1) ? 0 : 1;
    EXPECT_EQ(d.z, samples.first_sample(scene.groups[table].mesh));
    first_point += d.y;
  }
  EXPECT_EQ(next, draws.size());
}

// A pool (a landscape's tables) laid out anew with fewer plants chooses as a sampler made for
// those plants alone: the tables one after the other in its room, and none of what the room held
// before chosen.
TEST_F(GpuSampling, APoolRefilledWithFewerPlantsChoosesAsASamplerOfThoseAlone) {
  const std::size_t capacity = scene.groups[0].size() + scene.groups[1].size();
  const std::vector<GpuScene::DrawPlace> places = GpuScene(scene).point_mesh_places();
  GpuSampler pool(scene.groups, samples, places, {{0, 2, capacity}});
  pointgen::TableList full(scene.groups), fewer(scene.groups);
  pointgen::InstanceTable half{scene.groups[0].mesh, {}, {}, {}};
  for (std::size_t i = 0; i < scene.groups[0].size(); i += 2) half.add_from(scene.groups[0], i);
  fewer.replace(0, half);
  fewer.replace(1, {scene.groups[1].mesh, {}, {}, {}});
  for (const pointgen::TableList* tables : {&full, &fewer}) {
    pool.refill(0, *tables);
    pool.sample(view());
    GpuSampler alone(*tables, samples, places);
    alone.sample(view());
    const std::vector<GpuSampler::Count> in_pool = pool.read_counts(), expected = alone.read_counts();
    ASSERT_EQ(in_pool.size(), capacity);
    std::size_t chosen = 0;
    for (std::size_t plant = 0; plant < capacity; ++plant) {
      const GpuSampler::Count c = in_pool[plant];
      const GpuSampler::Count e = plant < expected.size() ? expected[plant] : GpuSampler::Count{};
      ASSERT_EQ(c.points, e.points) << "plant " << plant << " of " << expected.size();
      ASSERT_EQ(c.polygons, e.polygons) << "plant " << plant;
      ASSERT_EQ(c.band, e.band) << "plant " << plant;
      chosen += c.band.has_value();
    }
    EXPECT_GT(chosen, 100u);
    EXPECT_EQ(pool.first_plant(1), (*tables)[0].size());
  }
}

// What a band draws changes the depth pyramid only under its plants, so that
// DepthPyramid::build_changed rebuilds only the tiles there: each plant drawn marks the tiles
// under its bounds box's rectangle, and the sky between the plants stays unmarked.
TEST_F(GpuSampling, MarksThePyramidTilesUnderThePlantsItDraws) {
  std::ostringstream json;  // rows of beeches and ferns 40 to 105 m ahead, the sky between them
  json << R"({"camera": {"position": [0, 3, 0], "target": [0, 2, -60], "fov_y_deg": 50, "near": 0.5, "far": 1000},
             "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}], "objects": [)";
  for (int k = 0; k < 2; ++k) {
    json << (k ? ", " : "") << R"({"type": "plant", "species": ")" << (k ? "fern" : "beech") << R"(", "positions": [)";
    for (int z = 0; z < 5; ++z) {
      for (int x = 0; x < 6; ++x) json << (x || z ? ", " : "") << "[" << -70 + 28 * x + 3 * k << ", 0, " << -40 - 15 * z - 5 * k << "]";
    }
    json << "]}";
  }
  json << "]}";
  const Scene rows = load_scene({"rows.json", json.str(), [](const std::string&) { return std::nullopt; }});
  const PointSamples row_samples(rows, settings.points_per_triangle, true);
  GpuSampler gpu(rows.groups, row_samples, GpuScene(rows).point_mesh_places());
  const glm::ivec2 size(settings.width, settings.height);
  const DepthPyramid pyramid(size);
  const gl::Texture depth(GL_TEXTURE_2D);
  glTextureStorage2D(depth.name(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
  const float far_depth = 1.0f;
  glClearTexImage(depth.name(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far_depth);
  gl::Buffer no_points;
  gl::store(no_points, std::vector<GLuint>(static_cast<std::size_t>(size.x * size.y), 0xFFFFFFFFu));
  pyramid.build(depth.name(), no_points.name());  // nothing drawn: nothing hidden, no tile marked
  const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
  const glm::mat4 view_projection = rows.camera.projection(aspect) * rows.camera.view();
  gpu.begin(sampler_view(rows.camera, settings, {view_projection}), GpuSampler::bands(rows.camera.far));
  for (int b = 0; b < gpu.distance_band_count(); ++b) gpu.add_band(b, &pyramid);
  const std::vector<bool> marked = pyramid.read_changed_tiles();
  const glm::ivec2 tiles = pyramid.tile_counts();
  const std::vector<GpuSampler::Count> counts = gpu.read_counts();
  std::size_t drawn = 0;
  for (std::size_t t = 0; t < rows.groups.size(); ++t) {
    const pointgen::SampledMesh& mesh = row_samples.meshes()[rows.groups[t].mesh];
    for (std::size_t i = 0; i < rows.groups[t].size(); ++i) {
      const GpuSampler::Count& c = counts[gpu.first_plant(t) + i];
      if (!c.band || (c.points == 0 && !c.polygons)) continue;
      const std::optional<pointgen::ScreenRect> rect = pointgen::project_box(view_projection * rows.groups[t].transform(i), mesh.center, mesh.half_size);
      if (!rect) continue;
      ++drawn;
      const auto tile_of = [&](glm::vec2 ndc) {
        return glm::clamp(glm::ivec2(glm::floor((ndc * 0.5f + 0.5f) * glm::vec2(size))), glm::ivec2(0), size - 1) / 32;
      };
      const glm::ivec2 first = tile_of(rect->min), last = tile_of(rect->max);
      for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) ASSERT_TRUE(marked[static_cast<std::size_t>(y * tiles.x + x)]) << "plant " << i << " of table " << t;
      }
    }
  }
  ASSERT_GE(drawn, 40u) << "of the 60 plants most are in view";
  EXPECT_LT(std::count(marked.begin(), marked.end(), true), static_cast<std::ptrdiff_t>(marked.size() * 9 / 10)) << "the sky is left";
  pyramid.build_changed(depth.name(), no_points.name());
  const std::vector<bool> after = pyramid.read_changed_tiles();
  EXPECT_EQ(std::count(after.begin(), after.end(), true), 0) << "a build clears the marks";
}

// Seen with `settings`, `columns` × `rows` plants of `species` 0.2 m apart, 12.5 m ahead and on, in the ladder's band from
// 12 to 18 m, sorted into bands; per band the nearest and farthest of its plants' bounds centres
// from the eye.
std::map<int, std::pair<float, float>> band_reach(const RenderSettings& settings, const std::string& species, int columns, int rows) {
  std::ostringstream json;
  json << R"({"camera": {"position": [0, 3, 0], "target": [0, 2, -60], "fov_y_deg": 50, "near": 0.5, "far": 1000},
             "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}],
             "objects": [{"type": "plant", "species": ")" << species << R"(", "positions": [)";
  for (int x = 0; x < columns; ++x) {
    for (int z = 0; z < rows; ++z) json << (x || z ? ", " : "") << "[" << -0.1 * columns + 0.2 * x << ", 0, " << -12.5 - 0.2 * z << "]";
  }
  json << "]}]}";
  const Scene dense = load_scene({"dense.json", json.str(), [](const std::string&) { return std::nullopt; }});
  const PointSamples dense_samples(dense, settings.points_per_triangle, true);
  GpuSampler gpu(dense.groups, dense_samples, GpuScene(dense).point_mesh_places());
  const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
  pointgen::SamplerView v = sampler_view(dense.camera, settings, {dense.camera.projection(aspect) * dense.camera.view()});
  gpu.begin(v, GpuSampler::bands(dense.camera.far));
  for (int b = 0; b < gpu.band_count(); ++b) gpu.add_band(b, nullptr);
  const pointgen::SampledMesh& mesh = dense_samples.meshes()[dense.groups.front().mesh];
  std::map<int, std::pair<float, float>> reach;
  const std::vector<GpuSampler::Count> counts = gpu.read_counts();
  EXPECT_EQ(counts.size(), static_cast<std::size_t>(columns * rows));
  for (std::size_t i = 0; i < counts.size(); ++i) {
    EXPECT_TRUE(counts[i].band) << "every plant is in view";
    if (!counts[i].band) continue;
    const glm::vec3 center(dense.groups.front().transforms[i] * glm::vec4(mesh.center, 1.0f));
    const float d = glm::distance(center, dense.camera.position);
    auto [at, fresh] = reach.try_emplace(*counts[i].band, d, d);
    at->second = {std::min(at->second.first, d), std::max(at->second.second, d)};
  }
  return reach;
}

void expect_ordered_by_distance(const std::map<int, std::pair<float, float>>& reach) {
  for (auto a = reach.begin(), b = std::next(a); b != reach.end(); ++a, ++b) {
    EXPECT_LT(a->first, b->first);
    EXPECT_LE(a->second.second, b->second.first) << "band " << a->first << " reaches past band " << b->first;
  }
}

// A band of the ladder that holds more than a few thousand plants in view is cut into bands by
// distance (into the places of ladder bands with no plants): 2,500 ferns take several bands, each
// one's plants nearer the eye than the next one's.
TEST_F(GpuSampling, ADenseBandIsCutIntoBandsByDistance) {
  const std::map<int, std::pair<float, float>> reach = band_reach(settings, "fern", 100, 25);
  EXPECT_GE(reach.size(), 3u) << "the ladder's band should be cut";
  expect_ordered_by_distance(reach);
}

// What weighs is what a band draws: 300 beeches near enough to be drawn as polygons (3,628
// triangles each) are cut into bands, 300 ferns in the same places are not.
TEST_F(GpuSampling, ABandOfPolygonPlantsIsCutSoonerThanOneOfAsManySmallPlants) {
  const std::map<int, std::pair<float, float>> beeches = band_reach(settings, "beech", 30, 10);
  EXPECT_GE(beeches.size(), 2u) << "the beeches' band should be cut";
  expect_ordered_by_distance(beeches);
  EXPECT_EQ(band_reach(settings, "fern", 30, 10).size(), 1u);
}

// Over random depths, level 0 holds each pixel's nearest depth within a pixel of it, and each
// level above the farthest of the 2 × 2 texels below it, up to the top. (Where the image's sides
// are not multiples of 4, the base pass's levels 1 and 2 may hold farther depths along its edges.)
TEST(DepthPyramidBuild, EachLevelHoldsTheFarthestOfTheTexelsBelow) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const glm::ivec2 size(1024, 600);  // 4 × 4 blocks (the base pass's) fit
  std::vector<float> depths(static_cast<std::size_t>(size.x * size.y));
  pointgen::Random random(7);
  for (float& d : depths) d = random.uniform();
  const gl::Texture depth(GL_TEXTURE_2D);
  glTextureStorage2D(depth.name(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
  glTextureSubImage2D(depth.name(), 0, 0, 0, size.x, size.y, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
  gl::Buffer no_points;
  gl::store(no_points, std::vector<GLuint>(depths.size(), 0xFFFFFFFFu));
  const DepthPyramid pyramid(size);
  pyramid.build(depth.name(), no_points.name());

  std::vector<float> expected(depths.size());
  for (int y = 0; y < size.y; ++y) {
    for (int x = 0; x < size.x; ++x) {
      float nearest = 1.0f;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const glm::ivec2 p = glm::clamp(glm::ivec2(x + dx, y + dy), glm::ivec2(0), size - 1);
          nearest = std::min(nearest, depths[static_cast<std::size_t>(p.y * size.x + p.x)]);
        }
      }
      expected[static_cast<std::size_t>(y * size.x + x)] = nearest;
    }
  }
  glm::ivec2 below = size;
  ASSERT_GE(pyramid.levels(), 11u);
  for (std::size_t level = 0; level < pyramid.levels(); ++level) {
    ASSERT_EQ(pyramid.read(level), expected) << "level " << level;
    const glm::ivec2 above = (below + 1) / 2;
    std::vector<float> next(static_cast<std::size_t>(above.x * above.y), 0.0f);
    for (int y = 0; y < below.y; ++y) {
      for (int x = 0; x < below.x; ++x) {
        float& farthest = next[static_cast<std::size_t>((y / 2) * above.x + x / 2)];
        farthest = std::max(farthest, expected[static_cast<std::size_t>(y * below.x + x)]);
      }
    }
    expected = next;
    below = above;
  }
}

// Over a depth texture that changes between builds, build_changed keeps the pyramid where no pass
// marked a change, and build builds it again whole.
TEST(DepthPyramidBuild, IsKeptWhereNothingChangedAndBuiltAgainWhole) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const glm::ivec2 size(40, 24);
  const gl::Texture depth(GL_TEXTURE_2D);
  glTextureStorage2D(depth.name(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
  const auto fill = [&](float d) { glClearTexImage(depth.name(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &d); };
  gl::Buffer no_points;
  gl::store(no_points, std::vector<GLuint>(static_cast<std::size_t>(size.x * size.y), 0xFFFFFFFFu));
  const DepthPyramid pyramid(size);
  const auto all_at = [&](float d) {
    const std::vector<float> texels = pyramid.read(0);
    return std::all_of(texels.begin(), texels.end(), [d](float t) { return t == d; });
  };
  fill(0.75f);
  pyramid.build(depth.name(), no_points.name());
  EXPECT_TRUE(all_at(0.75f));
  fill(0.25f);
  pyramid.build_changed(depth.name(), no_points.name());
  EXPECT_TRUE(all_at(0.75f)) << "kept";
  pyramid.build(depth.name(), no_points.name());
  EXPECT_TRUE(all_at(0.25f)) << "built again";
  EXPECT_EQ(pyramid.read(pyramid.levels() - 1), std::vector<float>{0.25f}) << "to its top";
}

// A list of indirect draws, some empty (no indices or no instances), copied into one of several
// places: the copy holds the others in their order, and the counts the number of them and the
// triangles the whole list draws.
TEST(DrawnCommands, KeepsTheDrawsThatDrawInTheirOrderAndCountsThemAndTheirTriangles) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  constexpr std::size_t first = 300, count = 1000;  // not a multiple of the 256 threads
  std::vector<glm::uvec4> heads;                     // index count, instances, first index, base vertex
  std::vector<GLuint> commands;
  pointgen::Random random(11);
  for (std::size_t c = 0; c < first + count + 200; ++c) {
    const GLuint indices[] = {0, 3, 6, 30};
    const GLuint instances[] = {0, 1, 5};
    const glm::uvec4 head(indices[random.below(4)], instances[random.below(3)], random.below(1000), random.below(1000));
    heads.push_back(head);
    for (GLuint word : {head.x, head.y, head.z, head.w, static_cast<GLuint>(random.below(1000))}) commands.push_back(word);
  }
  gl::Buffer list;
  gl::store(list, commands);
  const DrawnCommands drawn(3, count);
  drawn.keep_drawn(list.name(), first, count, 2);

  std::vector<GLuint> expected;
  std::size_t triangles = 0;
  for (std::size_t c = first; c < first + count; ++c) {
    triangles += static_cast<std::size_t>(heads[c].x / 3) * heads[c].y;
    if (heads[c].x > 0 && heads[c].y > 0) expected.insert(expected.end(), commands.begin() + 5 * c, commands.begin() + 5 * c + 5);
  }
  ASSERT_GT(expected.size(), 0u);
  ASSERT_LT(expected.size(), 5 * count);
  const GpuScene::PlantDraws copy = drawn.from_copy({0, 0, list.name(), first, count}, 2);
  GLuint draws = 0;
  glGetNamedBufferSubData(copy.draw_counts, static_cast<GLintptr>(copy.count_slot * sizeof(GLuint)), sizeof draws, &draws);
  EXPECT_EQ(draws * 5, expected.size());
  std::vector<GLuint> kept(expected.size());
  glGetNamedBufferSubData(copy.commands, static_cast<GLintptr>(copy.first_command * GpuScene::command_bytes),
                          static_cast<GLsizeiptr>(kept.size() * sizeof(GLuint)), kept.data());
  EXPECT_EQ(kept, expected);
  EXPECT_EQ(drawn.read_triangles().at(2), triangles);
}

// A cascade draws the polygon plants that shadow the surfaces looking it up: a near beech under a
// high sun shadows the first cascade alone, and goes into that cascade's map alone; under a low
// sun behind the camera its shadow stretches into the far cascades, and is as large as the
// uniform map's of it.
TEST_F(GpuSampling, ACascadeDrawsThePlantsWhoseShadowsFallInIt) {
  settings.width = 480;
  settings.height = 270;
  settings.gpu_sampler = true;
  const auto render = [&](shadow::Method method, const std::string& direction) {
    settings.method = method;
    return render_shadows(R"({"camera": {"position": [0, 2, 0], "target": [0, 0, -20], "fov_y_deg": 50, "near": 0.5, "far": 300},
        "lights": [{"type": "directional", "direction": )" + direction + R"(}],
        "objects": [{"type": "plane", "center": [0, 0, -100], "size": [300, 300]},
                    {"type": "plant", "species": "beech", "positions": [[0, 0, -12]]}]})");
  };
  // The uniform map draws the plane and the whole beech (the frame draws the parts it shows).
  const std::size_t beech = render(shadow::Method::uniform, "[0.2, -1, 0.1]").stats.shadow_triangles - 2;
  ASSERT_GT(beech, 1000u) << "the beech is drawn as polygons";
  const Shadowed high = render(shadow::Method::cascades, "[0.2, -1, 0.1]");
  EXPECT_GT(high.shadowed, 200u);
  EXPECT_EQ(high.stats.shadow_triangles, 4 * 2 + beech) << "the plane in each cascade, the beech in the first alone";
  const Shadowed low = render(shadow::Method::cascades, "[0.7, -0.3, -0.65]"), uniform = render(shadow::Method::uniform, "[0.7, -0.3, -0.65]");
  EXPECT_GT(low.stats.shadow_triangles, 4 * 2 + beech) << "the beech in more cascades than the first";
  EXPECT_GT(uniform.shadowed, 1000u);
  EXPECT_NEAR(static_cast<double>(low.shadowed), static_cast<double>(uniform.shadowed), 0.15 * static_cast<double>(uniform.shadowed));
}

// A plant drawn by some of its polygon parts with each triangle's neighbours (the adjacency lists
// the silhouette and volume passes draw) draws those parts: seen from the side, the silhouette
// edges of a beech's upper parts lie within those parts' boxes, none down the trunk.
TEST_F(GpuSampling, APlantDrawnByPartsWithItsNeighboursDrawsThoseParts) {
  const Scene beech = load_scene({"beech.json", R"({"camera": {"position": [0, 5, 30], "target": [0, 5, 0]},
      "lights": [{"type": "directional", "direction": [0, 0, -1]}],
      "objects": [{"type": "plant", "species": "beech", "positions": [[0, 0, 0]]}]})",
                                  [](const std::string&) { return std::nullopt; }});
  const PointSamples beech_samples(beech, settings.points_per_triangle, true);
  GpuScene polygons(beech);
  polygons.gather_point_meshes();
  polygons.add_adjacency(beech);
  GpuSampler gpu(beech.groups, beech_samples, polygons.point_mesh_places());
  const std::size_t mesh = beech.groups.front().mesh;
  const std::vector<pointgen::PolygonPart>& parts = beech_samples.meshes()[mesh].polygon_parts;
  ASSERT_GE(parts.size(), 8u);
  shadow::Box tree;
  for (const pointgen::PolygonPart& part : parts) {
    tree.add(part.center - part.half_size);
    tree.add(part.center + part.half_size);
  }
  // The parts above the tree's middle, one indirect draw each, of plant 0.
  const float middle = tree.center().y;
  const GpuScene::DrawPlace place = polygons.point_mesh_places()[mesh];
  std::vector<GLuint> commands;
  std::vector<shadow::Box> drawn;
  for (const pointgen::PolygonPart& part : parts) {
    if (part.center.y - part.half_size.y < middle) continue;
    for (GLuint word : {part.index_count, 1u, place.first_index + part.first_index, static_cast<GLuint>(place.base_vertex), 0u}) commands.push_back(word);
    drawn.emplace_back().add(part.center - part.half_size);
    drawn.back().add(part.center + part.half_size);
  }
  ASSERT_GE(drawn.size(), 2u);
  ASSERT_LT(drawn.size(), parts.size());
  gl::Buffer command_list, plant_list, counts;
  gl::store(command_list, commands);
  gl::store(plant_list, std::vector<GLuint>{0});
  gl::store(counts, std::vector<GLuint>{static_cast<GLuint>(drawn.size())});
  GpuScene::PlantDraws draws = gpu.polygon_draws(0, 1);  // for its resident plants
  draws.plant_indices = plant_list.name();
  draws.commands = command_list.name();
  draws.first_command = 0;
  draws.command_count = drawn.size();
  draws.draw_counts = counts.name();
  draws.count_slot = 0;

  // An orthographic view along the light, the tree filling it.
  constexpr int size = 256;
  const glm::vec3 half = 0.55f * (tree.max - tree.min);
  const float side = std::max(half.x, half.y);
  const shadow::ShadowView view(glm::lookAt(tree.center() + glm::vec3(0, 0, 2 * half.z + 1), tree.center(), glm::vec3(0, 1, 0)),
                                glm::ortho(-side, side, -side, side, 0.5f, 4 * half.z + 2));
  const shadow::ShadowSetup setup{{view}, shadow::ViewSelection::single, "side"};
  SilhouettePass silhouettes(size);
  silhouettes.render(polygons, &draws, setup, 0, beech.lights[0]);
  std::vector<glm::vec2> points(static_cast<std::size_t>(size) * size);
  glGetTextureSubImage(silhouettes.points(), 0, 0, 0, 0, size, size, 1, GL_RG, GL_FLOAT,
                       static_cast<GLsizei>(points.size() * sizeof(glm::vec2)), points.data());

  // The cells of the drawn parts' boxes in the map, a cell wider each way.
  std::vector<bool> inside(points.size(), false);
  for (const shadow::Box& box : drawn) {
    glm::vec2 low(size), high(0.0f);
    for (int c = 0; c < 8; ++c) {
      const glm::vec4 clip = view.view_projection() * glm::vec4(box.corner(c), 1.0f);
      const glm::vec2 texel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * static_cast<float>(size);
      low = glm::min(low, texel);
      high = glm::max(high, texel);
    }
    for (int y = std::max(0, static_cast<int>(low.y) - 2); y < std::min(size, static_cast<int>(high.y) + 2); ++y) {
      for (int x = std::max(0, static_cast<int>(low.x) - 2); x < std::min(size, static_cast<int>(high.x) + 2); ++x) {
        inside[static_cast<std::size_t>(y * size + x)] = true;
      }
    }
  }
  std::size_t edges = 0, outside = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].x < 0.0f) continue;
    ++edges;
    outside += !inside[i];
  }
  std::cout << drawn.size() << " of " << parts.size() << " parts drawn: " << edges << " cells with an edge, " << outside
            << " outside the parts' boxes\n";
  EXPECT_GT(edges, 200u);
  EXPECT_EQ(outside, 0u);
}

// A paged map draws each tile of its pages with the polygon plants whose boxes reach the tile: a
// beech near the camera goes into the tiles over it alone, and its shadow stays the volumes'.
TEST_F(GpuSampling, APageTileDrawsThePolygonPlantsThatReachIt) {
  settings.width = 320;
  settings.height = 180;
  settings.gpu_sampler = true;
  const std::string scene = R"({"camera": {"position": [0, 3, 0], "target": [0, 0, -20], "fov_y_deg": 50, "near": 0.5, "far": 300},
      "lights": [{"type": "directional", "direction": [0.3, -1, -0.2]}],
      "objects": [{"type": "plane", "center": [0, 0, -100], "size": [300, 300]},
                  {"type": "plant", "species": "beech", "positions": [[0, 0, -10]]}]})";
  settings.method = shadow::Method::uniform;
  const std::size_t beech = render_shadows(scene).stats.shadow_triangles - 2;
  ASSERT_GT(beech, 1000u) << "the beech is drawn as polygons";
  const auto [paged, tiles, exact] = render_paged_and_exact(scene);
  std::cout << tiles << " tiles, " << paged.stats.shadow_triangles << " triangles (the beech " << beech << "); shadowed "
            << paged.shadowed << " pixels against the volumes' " << exact.shadowed << "\n";
  ASSERT_GE(tiles, 4u);
  EXPECT_LT(paged.stats.shadow_triangles, tiles * (2 + beech) / 2) << "the beech should be in fewer than half the tiles";
  ASSERT_GT(exact.shadowed, 2000u);
  EXPECT_NEAR(static_cast<double>(paged.shadowed), static_cast<double>(exact.shadowed), 0.05 * static_cast<double>(exact.shadowed));
}

// A large mesh drawn once, the terrain, goes into each view by its chunks that reach it: into the
// tiles of a paged map, of which none takes it whole, and into the frame, which sees part of it;
// the shadow of a box on it stays the volumes'.
TEST_F(GpuSampling, APageTileAndTheFrameDrawTheTerrainChunksThatReachThem) {
  settings.width = 320;
  settings.height = 180;
  settings.gpu_sampler = true;
  const std::string scene = R"({"camera": {"position": [0, 3, 0], "target": [0, 0, -20], "fov_y_deg": 50, "near": 0.5, "far": 300},
      "lights": [{"type": "directional", "direction": [0.6, -0.6, 0.3]}],
      "objects": [{"type": "ecosystem", "seed": 3, "size": [200, 200], "terrain": {"relief": 0, "resolution": 128},
                   "plants": [{"species": "fern", "count": 1}]},
                  {"type": "box", "min": [-4, 0, -16], "max": [2, 4, -12]}]})";
  std::size_t terrain = 0;
  const Scene loaded = load_scene({"scene.json", scene, [](const std::string&) { return std::nullopt; }});
  for (std::size_t m = 0; m < loaded.meshes.size(); ++m) {
    if (!loaded.point_meshes[m]) terrain = std::max(terrain, loaded.meshes[m].triangle_count());
  }
  ASSERT_GT(terrain, 20000u) << "the terrain is large enough to be drawn by chunks";
  const auto [paged, tiles, exact] = render_paged_and_exact(scene);
  std::cout << tiles << " tiles, " << paged.stats.shadow_triangles << " triangles (the terrain " << terrain << "); the frame "
            << paged.stats.triangles << "; shadowed " << paged.shadowed << " pixels against the volumes' " << exact.shadowed << "\n";
  ASSERT_GE(tiles, 4u);
  EXPECT_LT(paged.stats.shadow_triangles, tiles * (terrain + 12) / 2) << "each tile should draw less than half the terrain";
  EXPECT_LT(paged.stats.triangles, (terrain + 12) * 3 / 4) << "the frame sees less than half the terrain";
  ASSERT_GT(exact.shadowed, 1000u);
  EXPECT_NEAR(static_cast<double>(paged.shadowed), static_cast<double>(exact.shadowed), 0.03 * static_cast<double>(exact.shadowed));
}

TEST_F(GpuSampling, ItsFrameCoversWhatThePolygonsCover) {
  settings.method = shadow::Method::none;
  settings.points = false;
  Renderer polygons(scene, settings);
  polygons.render(scene.camera, scene.lights[0]);
  settings.points = settings.gpu_sampler = true;
  Renderer gpu(scene, settings);
  gpu.render(scene.camera, scene.lights[0]);
  EXPECT_GT(gpu.stats().points, 100000u);
  EXPECT_GT(gpu.stats().triangles, 0u);
  EXPECT_EQ(gpu.stats().points_left_out, 0u) << "the buffers hold every plant's whole list here";
  const Coverage c = compare(polygons.frame().read_depth(), gpu.frame().read_depth());
  ASSERT_GT(c.polygons, 100000u);
  EXPECT_LT(1.0 - static_cast<double>(c.both) / static_cast<double>(c.polygons), 0.02) << "holes";
  EXPECT_LT(static_cast<double>(c.points - c.both) / static_cast<double>(c.polygons), 0.1) << "points off the plants";
}

TEST_F(GpuSampling, PlantsBehindAWallAreLeftOut) {
  settings.method = shadow::Method::none;
  settings.gpu_sampler = true;
  Renderer open(scene, settings);
  open.render(scene.camera, scene.lights[0]);
  const Scene walled = load_scene({"walled.json", plantation(true), [](const std::string&) { return std::nullopt; }});
  Renderer behind(walled, settings);
  behind.render(walled.camera, walled.lights[0]);
  // The wall covers the middle of the view beyond 20 m, where most of the points are.
  EXPECT_LT(behind.stats().points, open.stats().points / 2);
  // What shows beside the wall is drawn as without it.
  const Image<float> a = open.frame().read_depth(), b = behind.frame().read_depth();
  std::size_t beside = 0, same = 0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    if (b.samples[i] < 0.0f || a.samples[i] < 0.0f || std::abs(b.samples[i] - 20.0f) < 1.5f) continue;
    ++beside;
    same += std::abs(a.samples[i] - b.samples[i]) < 0.01f * a.samples[i];
  }
  ASSERT_GT(beside, 50000u);
  EXPECT_GT(static_cast<double>(same) / static_cast<double>(beside), 0.97);
}

// Occluders close one-pixel gaps (DepthPyramid): a beech seen through a slit one pixel wide in a
// wall is left out, through one ten pixels wide it is drawn. A backdrop shows through both.
TEST_F(GpuSampling, APlantSeenThroughAOnePixelSlitIsLeftOutButNotThroughAWiderOne) {
  settings.method = shadow::Method::none;
  settings.gpu_sampler = true;
  // At 20 m a pixel is 2 × 20 m × tan 25° × 960 / 540 / 960 = 0.0345 m wide; the centre of the
  // pixel right of the middle is at 0.0173 m, in either slit, and no other pixel's is in the narrow one.
  const auto render = [&](float slit) {
    std::ostringstream s;
    s << R"({"camera": {"position": [0, 3, 0], "target": [0, 3, -60], "fov_y_deg": 50, "near": 0.5, "far": 400},
            "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}], "objects": [
            {"type": "box", "min": [-100, -50, -21], "max": [0, 60, -20]},
            {"type": "box", "min": [)" << slit << R"(, -50, -21], "max": [100, 60, -20]},
            {"type": "box", "min": [-300, -200, -301], "max": [300, 200, -300]},
            {"type": "plant", "species": "beech", "positions": [[0, 0, -60]]}]})";
    const Scene walled = load_scene({"slit.json", s.str(), [](const std::string&) { return std::nullopt; }});
    Renderer renderer(walled, settings);
    renderer.render(walled.camera, walled.lights[0]);
    const Image<float> depth = renderer.frame().read_depth();
    const auto seen_beyond = std::count_if(depth.samples.begin(), depth.samples.end(), [](float d) { return d > 40.0f; });
    EXPECT_GT(seen_beyond, 0) << "the slit should be open";
    return renderer.stats();
  };
  const FrameStats narrow = render(0.03f), wide = render(0.35f);
  EXPECT_EQ(narrow.points, 0u);
  EXPECT_EQ(narrow.triangles, 36u) << "the three boxes alone";
  EXPECT_GT(wide.points + wide.triangles, 36u);
}

// A near plant drawn as polygons draws the parts of it that nearer surfaces leave to be seen: a
// beech that a wall hides but for its right edge draws fewer triangles than without the wall, and
// each pixel shows the nearer of the wall and the beech drawn alone.
TEST_F(GpuSampling, APlantMostlyBehindAWallDrawsOnlyThePartsItShows) {
  settings.method = shadow::Method::none;
  settings.gpu_sampler = true;
  const auto render = [&](const std::string& objects) {
    const Scene s = load_scene({"half.json", R"({"camera": {"position": [0, 3, 0], "target": [0, 6, -40], "fov_y_deg": 50,
        "near": 0.5, "far": 400}, "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}], "objects": [)" + objects + "]}",
                                [](const std::string&) { return std::nullopt; }});
    Renderer renderer(s, settings);
    renderer.render(s.camera, s.lights[0]);
    return std::make_pair(renderer.frame().read_depth(), renderer.stats());
  };
  const std::string wall = R"({"type": "box", "min": [-100, -50, -21], "max": [2, 60, -20]})";
  const std::string beech = R"({"type": "plant", "species": "beech", "positions": [[0, 0, -40]]})";
  const auto [alone, alone_stats] = render(beech);
  const auto [wall_depth, wall_stats] = render(wall);
  const auto [both, both_stats] = render(wall + ", " + beech);
  ASSERT_EQ(alone_stats.points, 0u) << "the beech should be near enough to be drawn as polygons";
  const std::size_t whole = alone_stats.triangles, shown = both_stats.triangles - wall_stats.triangles;
  EXPECT_GT(shown, 0u);
  EXPECT_LT(shown, whole * 3 / 4) << "the parts behind the wall should be left out: " << shown << " of " << whole;
  std::size_t beech_pixels = 0, wrong = 0;
  for (std::size_t i = 0; i < both.samples.size(); ++i) {
    const float a = alone.samples[i], w = wall_depth.samples[i];
    const float expected = a < 0.0f ? w : w < 0.0f ? a : std::min(a, w);
    beech_pixels += a >= 0.0f && (w < 0.0f || a < w);
    wrong += std::abs(both.samples[i] - expected) > 1e-3f * std::max(expected, 1.0f);
  }
  ASSERT_GT(beech_pixels, 1000u) << "the beech should show beside the wall";
  EXPECT_EQ(wrong, 0u);
}

// The shadow map draws the camera's plants and the casters out of view whose shadows reach what
// the frame shows, and no others: a beech beside the view shadows the ground in it; behind a wall
// that hides that ground, or far behind the camera, it is left out.
TEST_F(GpuSampling, TheShadowMapTakesTheCastersOutOfViewThatShadowTheView) {
  const std::string start = R"({"camera": {"position": [0, 2, 0], "target": [0, 0, -20], "fov_y_deg": 40, "near": 0.5, "far": 200},
      "lights": [{"type": "directional", "direction": [1, -0.5, 0]}],
      "objects": [{"type": "plane", "center": [0, 0, -20], "size": [200, 200]})";
  const std::string wall = R"(, {"type": "box", "min": [-15, 0, -6], "max": [15, 10, -5]})";
  const std::string beside = R"(, {"type": "plant", "species": "beech", "positions": [[-35, 0, -20]]})";
  const std::string behind = R"(, {"type": "plant", "species": "beech", "positions": [[0, 0, 60]]})";
  settings.width = 320;
  settings.height = 180;
  settings.method = shadow::Method::psm;
  settings.gpu_sampler = true;
  const auto render = [&](const std::string& objects) { return render_shadows(start + objects + "]}"); };
  const Shadowed ground = render(""), seen = render(beside);
  EXPECT_GT(seen.shadowed, 500u) << "its shadow should lie across the view";
  EXPECT_GT(seen.stats.shadow_triangles, ground.stats.shadow_triangles) << "drawn into the map (near: as polygons)";
  EXPECT_EQ(seen.stats.triangles, ground.stats.triangles) << "but not into the frame, which does not show it";
  EXPECT_EQ(render(behind).stats.shadow_triangles, ground.stats.shadow_triangles) << "its shadow falls behind the camera";
  const Shadowed walled = render(wall), hidden = render(wall + beside);
  EXPECT_EQ(hidden.stats.shadow_triangles, walled.stats.shadow_triangles) << "its shadow falls on ground the wall hides";
  EXPECT_EQ(hidden.shadowed, walled.shadowed);
}

// A plant the frame hides still shadows what it shows: a beech behind a pillar casts its shadow
// towards the camera onto ground beside the pillar, as when every plant is drawn as polygons.
TEST_F(GpuSampling, APlantTheFrameHidesCastsItsShadowOnWhatTheFrameShows) {
  const std::string start = R"({"camera": {"position": [0, 2, 0], "target": [0, 0, -20], "fov_y_deg": 40, "near": 0.5, "far": 200},
      "lights": [{"type": "directional", "direction": [0.3, -0.5, 0.9]}],
      "objects": [{"type": "plane", "center": [0, 0, -20], "size": [200, 200]},
                  {"type": "box", "min": [-4, 0, -10.5], "max": [4, 40, -10]})";
  const std::string beech = R"(, {"type": "plant", "species": "beech", "positions": [[0, 0, -40]]})";
  settings.width = 320;
  settings.height = 180;
  settings.method = shadow::Method::psm;
  const auto render = [&](const std::string& objects, bool points) {
    settings.points = settings.gpu_sampler = points;
    return render_shadows(start + objects + "]}");
  };
  const Shadowed bare = render("", true), hidden = render(beech, true), polygons = render(beech, false);
  EXPECT_EQ(hidden.stats.points, 0u) << "the frame does not draw the beech";
  EXPECT_EQ(hidden.stats.triangles, bare.stats.triangles);
  ASSERT_GT(polygons.shadowed, bare.shadowed + 300) << "its shadow should lie beside the pillar";
  const auto gain = [&](const Shadowed& f) { return static_cast<double>(f.shadowed) - static_cast<double>(bare.shadowed); };
  EXPECT_NEAR(gain(hidden), gain(polygons), 0.25 * gain(polygons));
}

// A caster shadows only receivers farther from the light than itself: a beech beyond a wall from
// a low light has the wall's lit face before it in each cascade, and no cascade draws it.
TEST_F(GpuSampling, ACasterBeyondEveryReceiverFromTheLightIsLeftOut) {
  const std::string start = R"({"camera": {"position": [0, 2, 0], "target": [0, 0, -20], "fov_y_deg": 40, "near": 0.5, "far": 200},
      "lights": [{"type": "directional", "direction": [1, -0.2, 0]}],
      "objects": [{"type": "plane", "center": [0, 0, -20], "size": [200, 200]},
                  {"type": "box", "min": [5, 0, -30], "max": [6, 30, -10]})";
  const std::string beech = R"(, {"type": "plant", "species": "beech", "positions": [[30, 0, -20]]})";
  settings.width = 320;
  settings.height = 180;
  settings.method = shadow::Method::cascades;
  settings.gpu_sampler = true;
  const Shadowed bare = render_shadows(start + "]}"), beyond = render_shadows(start + beech + "]}");
  EXPECT_EQ(beyond.shadowed, bare.shadowed) << "nothing the frame shows lies beyond the beech from the light";
  EXPECT_EQ(beyond.stats.shadow_triangles, bare.stats.shadow_triangles);
}

// The shadow map draws the parts of a large polygon plant that may shadow what the frame shows: a
// beech half behind a wall, lit from behind the camera, casts the shadow of its hidden half onto
// ground the wall hides, and the map leaves that half out; the frame's shadows are those of every
// plant drawn whole.
TEST_F(GpuSampling, TheMapLeavesOutThePartsOfAPlantThatShadowNothingTheFrameShows) {
  const std::string scene = R"({"camera": {"position": [0, 6, 0], "target": [0, 0, -25], "fov_y_deg": 40, "near": 0.5, "far": 200},
      "lights": [{"type": "directional", "direction": [0.3, -1, -0.7]}],
      "objects": [{"type": "plane", "center": [0, 0, -20], "size": [200, 200]},
                  {"type": "box", "min": [-30, 0, -10.5], "max": [2, 30, -10]},
                  {"type": "plant", "species": "beech", "positions": [[0, 0, -25]]}]})";
  settings.width = 320;
  settings.height = 180;
  settings.method = shadow::Method::psm;
  settings.points = settings.gpu_sampler = false;
  const Shadowed whole = render_shadows(scene);
  settings.points = settings.gpu_sampler = true;
  const Shadowed parts = render_shadows(scene);
  const std::size_t ground_and_wall = 2 + 12, beech = whole.stats.triangles - ground_and_wall;
  ASSERT_GT(beech, 1000u) << "the beech is near enough to be drawn as polygons";
  ASSERT_EQ(parts.stats.points, 0u);
  EXPECT_LT(parts.stats.shadow_triangles - ground_and_wall, beech * 3 / 4) << "its hidden half should be left out of the map";
  ASSERT_GT(whole.shadowed, 1000u) << "its shadow should lie on the ground beside the wall";
  EXPECT_NEAR(static_cast<double>(parts.shadowed), static_cast<double>(whole.shadowed), 0.02 * static_cast<double>(whole.shadowed));
}

// A map whose texels are coarser than the frame's pixels takes of each plant no more of the
// camera's points than k a texel of half its surface (as a sampling made for the map would): a
// field of ferns in a 64² uniform map, whose texels per square metre the test reads from the map's
// orthographic matrix.
TEST_F(GpuSampling, ACoarseMapTakesOfEachPlantKPointsATexel) {
  std::ostringstream json;
  json << R"({"camera": {"position": [0, 1.5, 0], "target": [0, 0, -20], "fov_y_deg": 40, "near": 0.5, "far": 200},
      "lights": [{"type": "directional", "direction": [0.3, -1, -0.2]}],
      "objects": [{"type": "plane", "center": [0, 0, -20], "size": [120, 120]}, )"
       << test::plant_grid_json("fern", 40, 8, -10, 3, -30, -6) << "]}";
  const Scene ferns = load_scene({"ferns.json", json.str(), [](const std::string&) { return std::nullopt; }});
  settings.method = shadow::Method::uniform;
  settings.shadow_size = 128;
  settings.gpu_sampler = true;
  Renderer renderer(ferns, settings);
  renderer.render(ferns.camera, ferns.lights[0]);
  const FrameStats stats = renderer.stats();
  const glm::mat4 map = renderer.shadow_setup().views.at(0).view_projection();
  const float texels_per_square_metre = glm::length(glm::vec3(glm::row(map, 0))) * glm::length(glm::vec3(glm::row(map, 1))) * 0.25f *
                                        static_cast<float>(settings.shadow_size * settings.shadow_size);
  const PointSamples fern_samples{ferns, settings.points_per_triangle, true};
  double most = 0.0;
  for (const pointgen::InstanceTable& table : ferns.groups) {
    const float area = fern_samples.meshes()[table.mesh].area;
    if (fern_samples.meshes()[table.mesh].samples == 0) continue;
    for (const glm::mat4x3& model : table.transforms) {
      const float scale = std::cbrt(std::abs(glm::determinant(glm::mat3(model))));
      most += std::floor(settings.k * 0.5f * area * scale * scale * texels_per_square_metre) + 1.0;
    }
  }
  ASSERT_GT(stats.points, static_cast<std::size_t>(2.0 * most)) << "the frame should hold more points than the map may take";
  EXPECT_GT(stats.shadow_points, 0u);
  EXPECT_LE(static_cast<double>(stats.shadow_points), most);
}

// A plant the frame draws as polygons goes into a map as points where that map asks fewer points
// of it than would be cheaper as polygons (a coarse texel is shadowed only where its centre meets
// a leaf, but wholly by a splat): a near beech in a 128² uniform map, its shadow still cast; in a
// 4096² map it stays polygons.
TEST_F(GpuSampling, ACoarseMapDrawsAsPointsAPlantTheFrameDrawsAsPolygons) {
  const std::string scene = R"({"camera": {"position": [0, 4, 0], "target": [0, 2, -20], "fov_y_deg": 50, "near": 0.5, "far": 200},
      "lights": [{"type": "directional", "direction": [0.4, -1, -0.3]}],
      "objects": [{"type": "plane", "center": [0, 0, -20], "size": [100, 100]},
                  {"type": "plant", "species": "beech", "positions": [[0, 0, -14]]}]})";
  settings.width = 320;
  settings.height = 180;
  settings.method = shadow::Method::uniform;
  settings.gpu_sampler = true;
  settings.shadow_size = 4096;
  const Shadowed fine = render_shadows(scene);
  settings.shadow_size = 128;
  const Shadowed coarse = render_shadows(scene);
  const std::size_t ground = 2;
  ASSERT_GT(coarse.stats.triangles, ground + 500) << "the frame draws the beech as polygons";
  EXPECT_EQ(coarse.stats.triangles, fine.stats.triangles);
  EXPECT_GT(fine.stats.shadow_triangles, ground + 500) << "the fine map draws it as polygons";
  EXPECT_EQ(coarse.stats.shadow_triangles, ground) << "the coarse map does not";
  EXPECT_GT(coarse.stats.shadow_points, 0u) << "but as points";
  EXPECT_GT(coarse.shadowed, 300u) << "its shadow should lie on the ground";
}

// A frame of a scene without plants draws no points, and runs none of the sampler's passes, its
// pyramids or the splat passes over nothing (they took two thirds of such a frame on llvmpipe).
TEST_F(GpuSampling, AFrameWithoutPlantsDrawsNoneAndRunsNoPointPasses) {
  const Scene bare = load_scene({"bare.json", R"({"camera": {"position": [0, 3, 8], "target": [0, 0, 0]},
      "lights": [{"type": "directional", "direction": [0.3, -1, 0.2]}],
      "objects": [{"type": "plane", "center": [0, 0, 0], "size": [40, 40]}, {"type": "box", "min": [-1, 0, -1], "max": [1, 2, 1]}]})",
                                 [](const std::string&) { return std::nullopt; }});
  settings.method = shadow::Method::psm;
  settings.gpu_sampler = true;
  Renderer renderer(bare, settings);
  renderer.render(bare.camera, bare.lights[0]);
  EXPECT_EQ(renderer.stats().points, 0u);
  EXPECT_EQ(renderer.stats().triangles, 14u);  // the plane's 2 and the box's 12
  std::set<std::string> stages;
  for (const auto& stage : renderer.stats().stage_ms) stages.insert(stage.first);
  EXPECT_TRUE(stages.count("polygons") && stages.count("map polygons") && stages.count("shading"));
  for (const char* stage : {"choice", "occlusion", "splats", "map splats"}) EXPECT_EQ(stages.count(stage), 0u) << stage;
}

// The GPU stages partition the frame's GPU time: each pass's time lies within their sum, and every
// stage of a shadowed frame with points and polygon plants took part.
TEST_F(GpuSampling, AFramesGpuStagesCoverItsPasses) {
  settings.method = shadow::Method::psm;
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  const FrameStats stats = renderer.stats();
  double sum = 0.0;
  std::map<std::string, double> stages;
  for (const auto& [stage, ms] : stats.stage_ms) {
    EXPECT_GE(ms, 0.0) << stage;
    stages[stage] = ms;
    sum += ms;
  }
  for (const char* stage : {"polygons", "choice", "occlusion", "splats", "map choice", "map polygons", "map splats", "shading"}) {
    EXPECT_EQ(stages.count(stage), 1u) << stage;
  }
  ASSERT_GT(stats.frame_pass_ms, 0.0);
  EXPECT_GE(sum, 0.999 * (stats.frame_pass_ms + stats.shadow_pass_ms)) << "the stages start before the passes and end after them";
}

}  // namespace
}  // namespace ecoview
