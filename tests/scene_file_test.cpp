// Scene files: every object type loads with the values written; every kind of bad input is an
// InputError naming the file and the field.
#include "app/cli/scene_info.hpp"
#include "app/errors.hpp"
#include "app/scene/landscape_fields.hpp"
#include "app/scene/scene_file.hpp"
#include "pointgen/landscape/ground_chunks.hpp"
#include "pointgen/landscape/landscape_cells.hpp"
#include "pointgen/landscape/landscape_pool.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <map>

#include "pointgen/movers/moving_set.hpp"

namespace ecoview {
namespace {

const char* camera_and_light = R"("camera": {"position": [0, 8, 12], "target": [0, 0, 0]},
  "lights": [{"type": "directional", "direction": [0.3, -1, 0.2]}])";

// A tetrahedron in OBJ.
const char* tetrahedron_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

Scene load_text(const std::string& json, std::map<std::string, std::string> files = {}) {
  return load_scene({"test.json", json, [files](const std::string& path) -> std::optional<std::string> {
                       const auto it = files.find(path);
                       if (it == files.end()) return std::nullopt;
                       return it->second;
                     }});
}

Scene load_objects(const std::string& objects, std::map<std::string, std::string> files = {}) {
  return load_text(std::string("{") + camera_and_light + ", \"objects\": [" + objects + "]}", std::move(files));
}

// World bounds of one instance.
shadow::Box instance_bounds(const Scene& scene, std::size_t group, std::size_t instance) {
  const pointgen::Bounds local = scene.meshes[scene.groups[group].mesh].bounds();
  shadow::Box box;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? local.max.x : local.min.x, (i & 2) ? local.max.y : local.min.y,
                      (i & 4) ? local.max.z : local.min.z);
    box.add(glm::vec3(scene.groups[group].transforms[instance] * glm::vec4(c, 1.0f)));
  }
  return box;
}

void expect_near(const glm::vec3& a, const glm::vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-4f);
  EXPECT_NEAR(a.y, b.y, 1e-4f);
  EXPECT_NEAR(a.z, b.z, 1e-4f);
}

TEST(SceneFile, PlaneKeepsCentreSizeAndColour) {
  const Scene s = load_objects(R"({"type": "plane", "center": [1, 2, 3], "size": [10, 4], "color": [1, 0.5, 0]})");
  ASSERT_EQ(s.groups.size(), 1u);
  const shadow::Box b = instance_bounds(s, 0, 0);
  expect_near(b.min, {-4, 2, 1});
  expect_near(b.max, {6, 2, 5});
  // Colours are sRGB in the file, linear in the scene (kept to pack_tint's steps, 0.0013 here).
  const glm::vec3 tint = s.groups[0].tint(0);
  EXPECT_NEAR(tint.r, 1.0f, 0.002f);
  EXPECT_NEAR(tint.g, 0.21404f, 0.001f);
  EXPECT_EQ(tint.b, 0.0f);
}

TEST(SceneFile, BoxesShareOneMeshAndKeepTheirCorners) {
  const Scene s = load_objects(R"({"type": "box", "min": [-1, 1, -1], "max": [1, 3, 2]},
                                  {"type": "box", "min": [5, 0, 5], "max": [6, 1, 6]})");
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_EQ(s.groups[0].transforms.size(), 2u);
  expect_near(instance_bounds(s, 0, 0).min, {-1, 1, -1});
  expect_near(instance_bounds(s, 0, 0).max, {1, 3, 2});
  expect_near(instance_bounds(s, 0, 1).max, {6, 1, 6});
}

TEST(SceneFile, SphereKeepsCentreAndRadius) {
  const Scene s = load_objects(R"({"type": "sphere", "center": [3, 1, 0], "radius": 2})");
  expect_near(instance_bounds(s, 0, 0).min, {1, -1, -2});
  expect_near(instance_bounds(s, 0, 0).max, {5, 3, 2});
}

TEST(SceneFile, MeshIsLoadedOnceAndDrawnPerTransform) {
  const Scene s = load_objects(
      R"({"type": "mesh", "file": "tet.obj", "transforms": [[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1],
                                                           [2,0,0,0, 0,2,0,0, 0,0,2,0, 10,0,0,1]]},
         {"type": "mesh", "file": "tet.obj"})",
      {{"tet.obj", tetrahedron_obj}});
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangle_count(), 4u);
  ASSERT_EQ(s.instance_count(), 3u);
  expect_near(instance_bounds(s, 0, 1).min, {10, 0, 0});
  expect_near(instance_bounds(s, 0, 1).max, {12, 2, 2});
  EXPECT_EQ(s.triangle_count(), 12u);
}

// "points": true makes a file's mesh a point mesh (a species); the same file without it is a
// mesh of its own, always polygons. An ecosystem's plants may come from the user's file.
TEST(SceneFile, MeshesFromFilesBecomeSpeciesAsPointsAndInEcosystems) {
  const Scene s = load_objects(
      R"({"type": "mesh", "file": "tet.obj", "points": true}, {"type": "mesh", "file": "tet.obj"},
         {"type": "ecosystem", "size": [40, 40], "plants": [{"file": "tet.obj", "count": 25, "layer": "bushes", "scale": [2, 3]}]})",
      {{"tet.obj", tetrahedron_obj}});
  ASSERT_EQ(s.meshes.size(), 4u) << "the file as points, as polygons, the terrain, the ecosystem's species";
  EXPECT_EQ(s.point_meshes, (std::vector<bool>{true, false, false, true}));
  EXPECT_EQ(s.meshes[3].triangle_count(), 4u);
  ASSERT_EQ(s.groups.back().mesh, 3u);
  EXPECT_EQ(s.groups.back().size(), 25u);
}

// Each channel of the tints of a group's instances: the smallest and the largest, each checked
// within [1 - tint, 1 + tint] and the 0.2 % the packing may add (instance_table.hpp).
std::pair<float, float> tint_range(const pointgen::InstanceTable& group, float tint) {
  float lo = 2.0f, hi = 0.0f;
  for (std::size_t i = 0; i < group.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const float t = group.tint(i)[c];
      EXPECT_GE(t, (1.0f - tint) * 0.998f) << i;
      EXPECT_LE(t, (1.0f + tint) * 1.002f) << i;
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
  }
  return {lo, hi};
}

TEST(SceneFile, AFileSpeciesKeepsItsMeshColoursUnlessGivenATint) {
  const std::map<std::string, std::string> tet{{"tet.obj", tetrahedron_obj}};
  const std::string plants = R"({"type": "ecosystem", "size": [40, 40], "plants": [{"file": "tet.obj", "count": 60)";
  const Scene plain = load_objects(plants + "}]}", tet);
  ASSERT_EQ(plain.groups.back().size(), 60u);
  for (const std::uint32_t tint : plain.groups.back().tints) EXPECT_EQ(tint, pointgen::pack_tint(glm::vec3(1.0f)));
  const Scene tinted = load_objects(plants + R"(, "tint": 0.3}]})", tet);
  const auto [lo, hi] = tint_range(tinted.groups.back(), 0.3f);
  EXPECT_LT(lo, 0.8f);
  EXPECT_GT(hi, 1.2f);
}

TEST(SceneFile, ACatalogueSpeciesVariesByTwelvePercentUnlessGivenATint) {
  const std::string plants = R"({"type": "ecosystem", "size": [40, 40], "plants": [{"species": "hazel", "count": 60, "variants": 1)";
  const auto [lo, hi] = tint_range(load_objects(plants + "}]}").groups.back(), 0.12f);
  EXPECT_LT(lo, 0.92f);
  EXPECT_GT(hi, 1.08f);
  const Scene untinted = load_objects(plants + R"(, "tint": 0}]})");
  for (const std::uint32_t tint : untinted.groups.back().tints) EXPECT_EQ(tint, pointgen::pack_tint(glm::vec3(1.0f)));
}

TEST(SceneFile, CameraAndEveryLightTypeKeepTheirFields) {
  const Scene s = load_text(R"({"camera": {"position": [1, 2, 3], "target": [0, 1, 0], "up": [0, 0, 1],
                                           "fov_y_deg": 35, "near": 0.5, "far": 90},
    "lights": [{"type": "directional", "direction": [0, -2, 0]},
               {"type": "point", "position": [4, 5, 6]},
               {"type": "spot", "position": [0, 10, 0], "direction": [0, -1, 0], "cone_deg": 25}],
    "objects": [{"type": "plane", "center": [0, 0, 0], "size": [4, 4]}]})");
  expect_near(s.camera.position, {1, 2, 3});
  expect_near(s.camera.up, {0, 0, 1});
  EXPECT_FLOAT_EQ(s.camera.fov_y_deg, 35.0f);
  EXPECT_FLOAT_EQ(s.camera.near, 0.5f);
  EXPECT_FLOAT_EQ(s.camera.far, 90.0f);
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].type, shadow::LightType::directional);
  expect_near(s.lights[0].direction, {0, -1, 0});  // normalized
  EXPECT_EQ(s.lights[1].type, shadow::LightType::point);
  expect_near(s.lights[1].position, {4, 5, 6});
  EXPECT_EQ(s.lights[2].type, shadow::LightType::spot);
  EXPECT_FLOAT_EQ(s.lights[2].cone_deg, 25.0f);
}

// Loading `json` fails with a message that contains every one of `parts`.
void expect_input_error(const std::string& json, std::initializer_list<const char*> parts,
                        std::map<std::string, std::string> files = {}) {
  try {
    load_text(json, std::move(files));
    ADD_FAILURE() << "no error for:\n" << json;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const char* part : parts) EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}

std::string with_objects(const std::string& objects) {
  return std::string("{") + camera_and_light + ", \"objects\": [" + objects + "]}";
}

TEST(SceneFileErrors, SyntaxErrorNamesFileAndLine) {
  expect_input_error("{\n  \"camera\": {\n    \"position\": [0, 8 12]\n", {"test.json:3:", "invalid JSON"});
  expect_input_error(with_objects("").substr(0, 40), {"test.json:", "invalid JSON"});  // truncated
}

TEST(SceneFileErrors, JsonNestedDeeperThan256LevelsIsRefusedAtItsPlace) {
  // '{' opens the first level, so the 256th '[', at byte 267, opens the 257th: column 268.
  const std::string deep = "{\"comment\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  expect_input_error(deep, {"test.json:1:268: invalid JSON: nested deeper than 256 levels"});
}

TEST(SceneFileErrors, NaNAndInfinityAreRejected) {
  expect_input_error(R"({"camera": {"position": [0, 8, NaN], "target": [0, 0, 0]}})", {"test.json:1:", "invalid JSON"});
  expect_input_error(R"({"camera": {"position": [0, 8, Infinity], "target": [0, 0, 0]}})", {"test.json:1:"});
  expect_input_error(R"({"camera": {"position": [0, 8, 1e999], "target": [0, 0, 0]}})", {"test.json:1:", "overflow"});
}

TEST(SceneFileErrors, HugeNumbersAreOutOfRange) {
  expect_input_error(R"({"camera": {"position": [0, 8, 1e300], "target": [0, 0, 0]}, "lights": [], "objects": []})",
                     {"camera.position[2]", "between"});
}

TEST(SceneFileErrors, UnknownObjectTypeNamesTheField) {
  expect_input_error(with_objects(R"({"type": "cone"})"), {"test.json", "objects[0].type", "cone"});
}

TEST(SceneFileErrors, UnknownKeyIsNamed) {
  expect_input_error(with_objects(R"({"type": "box", "min": [0,0,0], "max": [1,1,1], "colour": [1,0,0]})"),
                     {"objects[0].colour", "unknown key"});
}

TEST(SceneFileErrors, WrongArrayLengthsAndTypes) {
  expect_input_error(R"({"camera": {"position": [0, 8], "target": [0, 0, 0]}})", {"camera.position", "3 numbers"});
  expect_input_error(R"({"camera": {"position": [0, 8, 1], "target": "x"}})", {"camera.target", "a string"});
  expect_input_error(with_objects(R"({"type": "plane", "center": [0,0,0], "size": [1, 2, 3]})"), {"objects[0].size"});
  expect_input_error(with_objects(R"({"type": "mesh", "file": "t.obj", "transforms": [[1, 0, 0]]})"),
                     {"objects[0].transforms[0]", "16 numbers"}, {{"t.obj", tetrahedron_obj}});
  expect_input_error(with_objects(R"({"type": "sphere", "center": [0,0,0], "radius": "big"})"), {"objects[0].radius"});
  expect_input_error(R"([1, 2])", {"test.json", "top level", "object"});
}

TEST(SceneFileErrors, ImpossibleGeometryIsNamed) {
  expect_input_error(with_objects(R"({"type": "box", "min": [0,0,0], "max": [1,0,1]})"), {"objects[0].max"});
  expect_input_error(with_objects(R"({"type": "sphere", "center": [0,0,0], "radius": 0})"), {"objects[0].radius"});
  expect_input_error(with_objects(R"({"type": "mesh", "file": "t.obj", "transforms": [[0,0,0,0, 0,0,0,0, 0,0,0,0, 0,0,0,1]]})"),
                     {"objects[0].transforms[0]", "singular"}, {{"t.obj", tetrahedron_obj}});
  expect_input_error(R"({"camera": {"position": [0, 8, 1], "target": [0, 8, 1]}})", {"camera", "target"});
  expect_input_error(R"({"camera": {"position": [0, 8, 0], "target": [0, 0, 0]}})", {"camera", "parallel"});
  expect_input_error(R"({"camera": {"position": [0, 8, 1], "target": [0, 0, 0], "near": 5, "far": 1}})", {"camera.far"});
}

TEST(SceneFileErrors, ZeroLengthLightDirectionAndBadConeAreNamed) {
  expect_input_error(R"({"camera": {"position": [0, 8, 12], "target": [0, 0, 0]},
                         "lights": [{"type": "directional", "direction": [0, 0, 0]}], "objects": []})",
                     {"lights[0].direction", "zero length"});
  expect_input_error(R"({"camera": {"position": [0, 8, 12], "target": [0, 0, 0]},
                         "lights": [{"type": "spot", "position": [0, 9, 0], "direction": [0, -1, 0], "cone_deg": 120}],
                         "objects": []})",
                     {"lights[0].cone_deg"});
  expect_input_error(R"({"camera": {"position": [0, 8, 12], "target": [0, 0, 0]}, "lights": [], "objects": []})",
                     {"lights", "at least 1"});
}

TEST(SceneFileErrors, MissingOrCorruptMeshNamesTheObjectAndFile) {
  expect_input_error(with_objects(R"({"type": "mesh", "file": "nothere.glb"})"),
                     {"test.json", "objects[0].file", "nothere.glb", "no such file"});
  expect_input_error(with_objects(R"({"type": "mesh", "file": "bad.glb"})"), {"objects[0].file", "bad.glb", "glTF"},
                     {{"bad.glb", "glTF\x02\0\0\0garbage"}});
  expect_input_error(with_objects(R"({"type": "mesh", "file": "bad.obj"})"), {"objects[0].file", "bad.obj"},
                     {{"bad.obj", "v 1 2\nf 1 2 3\n"}});
  expect_input_error(with_objects(R"({"type": "mesh", "file": "bad.off"})"), {"objects[0].file", "bad.off"},
                     {{"bad.off", "OFF\n99999999999 1 0\n"}});
  expect_input_error(with_objects(R"({"type": "mesh", "file": "model.fbx"})"), {"objects[0].file", "unknown mesh format"},
                     {{"model.fbx", "x"}});
}

TEST(SceneFileErrors, MalformedSpeciesAndCrowdsNameTheField) {
  const std::string eco = R"({"type": "ecosystem", "size": [50, 50], "plants": [)";
  expect_input_error(with_objects(eco + R"({"species": "baobab", "count": 3}]})"), {"objects[0].plants[0].species", "baobab"});
  expect_input_error(with_objects(eco + R"({"species": {"name": "x", "kind": "mushroom"}, "count": 3}]})"),
                     {"objects[0].plants[0].species.kind", "mushroom"});
  expect_input_error(with_objects(eco + R"({"species": {"like": "oak", "height": -2}, "count": 3}]})"),
                     {"objects[0].plants[0].species.height"});
  expect_input_error(with_objects(eco + R"({"species": {"kind": "bush"}, "count": 3}]})"),
                     {"objects[0].plants[0].species", "name"});
  expect_input_error(with_objects(eco + R"({"species": "oak", "count": -1}]})"), {"objects[0].plants[0].count"});
  expect_input_error(with_objects(eco + R"({"species": "oak", "count": 3, "variants": 0}]})"), {"objects[0].plants[0].variants"});
  const std::map<std::string, std::string> tet{{"tet.obj", tetrahedron_obj}};
  expect_input_error(with_objects(eco + R"({"file": "tet.obj", "count": 3, "layer": "canopy"}]})"),
                     {"objects[0].plants[0].layer", "canopy", "trees, bushes, ground"}, tet);
  expect_input_error(with_objects(eco + R"({"file": "tet.obj", "count": 3, "scale": [2, 1]}]})"), {"objects[0].plants[0].scale"}, tet);
  expect_input_error(with_objects(eco + R"({"file": "tet.obj", "species": "oak", "count": 3}]})"), {"objects[0].plants[0].file"}, tet);
  expect_input_error(with_objects(eco + R"({"file": "gone.obj", "count": 3}]})"), {"objects[0].plants[0].file", "gone.obj"});
  expect_input_error(with_objects(eco + R"({"file": "tet.obj", "count": 3, "tint": 1.5}]})"),
                     {"objects[0].plants[0].tint", "between 0 and 1"}, tet);
  expect_input_error(with_objects(eco + R"({"species": "oak", "count": 3, "tint": "none"}]})"),
                     {"objects[0].plants[0].tint", "expected a number"});
  expect_input_error(with_objects(R"({"type": "mesh", "file": "tet.obj", "points": "yes"})"), {"objects[0].points", "true or false"}, tet);
  expect_input_error(with_objects(R"({"type": "crowd", "count": -5, "center": [0, 0, 0], "size": [10, 10]})"),
                     {"objects[0].count"});
  expect_input_error(with_objects(R"({"type": "crowd", "count": 5, "center": [0, 0, 0], "size": [10, 10], "avoid": [[1, 1, 0, 0]]})"),
                     {"objects[0].avoid[0]", "x0 < x1"});
  expect_input_error(with_objects(R"({"type": "crowd", "count": 5, "center": [0, 0], "size": [10, 10]})"), {"objects[0].center"});
  expect_input_error(with_objects(R"({"type": "traffic", "cars": 5})"), {"objects[0].cars", "loops"});
  expect_input_error(with_objects(R"({"type": "ecosystem", "size": [50, 50], "plants": [{"species": "oak", "count": 1}],
                                      "animals": [{"kind": "dragon", "count": 1}]})"), {"objects[0].animals[0].kind"});
}

TEST(SceneFileErrors, AScenePastTheMemoryBudgetIsRefusedBeforeItIsBuilt) {
  const std::string huge = with_objects(R"({"type": "plane", "center": [0, 0, 0], "size": [4, 4]},
      {"type": "ecosystem", "size": [5000, 5000], "plants": [{"species": "meadow grass", "count": 90000000}]})");
  try {
    load_scene({"test.json", huge, [](const std::string&) { return std::nullopt; }}, {1024.0 * 1024.0 * 1024.0});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("objects[1]"), std::string::npos) << message;
    EXPECT_NE(message.find("memory budget of 1.00 GiB"), std::string::npos) << message;
    EXPECT_NE(message.find("would need about 22.1"), std::string::npos) << message;  // 9e7 plants x 264 bytes
  }
}

// A small landscape: trees of two species (one the user's, on low ground) and grass on gentle
// slopes, made within 60 m of the camera at (0, 8, 12).
const char* small_landscape = R"({"type": "landscape", "size": [2000, 2000], "radius": 60, "ground_cells": 32,
    "terrain": {"relief": 40, "feature": 300},
    "layers": [{"name": "trees", "cell_size": 20, "density": 0.01,
                "species": [{"species": "birch"}, {"file": "tet.obj", "weight": 2, "scale": [2, 3], "altitude": [-1000, 5]}]},
               {"cell_size": 5, "density": 0.2, "species": [{"species": "meadow grass", "slope_max_deg": 30}]}]})";

// The object as the scene file reads it (scene seed 1), for making its cells here.
LandscapeObject read_small_landscape() {
  const nlohmann::json document = nlohmann::json::parse(small_landscape);
  return read_landscape(JsonField(document, "test.json"), 1, [](const JsonField&) { return pointgen::TriangleMesh{}; });
}

TEST(SceneFile, LandscapeHasAnEmptyTableASpeciesAPoolForItsReachAndItsGroundForTheCamera) {
  const Scene s = load_objects(small_landscape, {{"tet.obj", tetrahedron_obj}});
  const LandscapeObject landscape = read_small_landscape();
  const pointgen::LandscapeSpec& spec = landscape.spec;
  // The scene says what the whole landscape stands for; the renderer makes its cells.
  EXPECT_EQ(s.landscape_plants, pointgen::expected_plant_count(spec));
  EXPECT_NE(describe_scene(s, 0.0).find(", a landscape of about "), std::string::npos) << describe_scene(s, 0.0);
  ASSERT_EQ(s.landscapes.size(), 1u);
  const LandscapeSource& source = s.landscapes[0];
  EXPECT_EQ(source.reach, (std::vector<float>{60.0f, 60.0f}));
  ASSERT_EQ(s.groups.size(), 7u) << "the ground, then birches, the user's, grass, and each again for far blocks";
  EXPECT_EQ(source.first_group, 1u);
  EXPECT_EQ(source.group_count(), 6u);
  for (std::size_t g = 1; g < 7; ++g) {
    EXPECT_EQ(s.groups[g].size(), 0u);
    EXPECT_TRUE(s.point_meshes[s.groups[g].mesh]) << "plants are drawn as points far away";
    EXPECT_EQ(s.groups[g].rounds_up, g >= 4) << "a far block's plants round up to a point";
    if (g >= 4) {
      EXPECT_EQ(s.groups[g].mesh, s.groups[g - 3].mesh);
    }
  }
  // Every site of the cells a 75 m disc can meet (60 m and the band beyond; trees' 20 m cells of
  // 2 × 2 sites, grass's 5 m of 3 × 3), and room for far blocks' plants.
  EXPECT_EQ(source.capacity, 9u * 9u * 4u + 32u * 32u * 9u + pointgen::LandscapePool::far_plants);
  // The ground: chunks of 32 × 32 squares (ground_cells) for the camera, over the whole area.
  ASSERT_EQ(source.ground_mesh, s.groups[0].mesh);
  EXPECT_FALSE(s.point_meshes[source.ground_mesh]);
  EXPECT_EQ(source.ground.cells, 32);
  pointgen::GroundChunks chunks(spec, source.ground);
  const pointgen::TriangleMesh expected = chunks.mesh(chunks.chosen(s.camera.position)).mesh;
  const pointgen::TriangleMesh& ground = s.meshes[source.ground_mesh];
  ASSERT_EQ(ground.positions.size(), expected.positions.size());
  EXPECT_EQ(std::memcmp(ground.positions.data(), expected.positions.data(), ground.positions.size() * sizeof(glm::vec3)), 0);
  EXPECT_EQ(ground.bounds().min.x, -1000.0f);
  EXPECT_EQ(ground.bounds().max.z, 1000.0f);
  // The bounds hold the whole landscape, whose ground lies between its lowest and highest hills.
  const shadow::Box bounds = s.bounds();
  EXPECT_LE(bounds.min.x, -1000.0f);
  EXPECT_GE(bounds.max.z, 1000.0f);
  EXPECT_LE(bounds.min.y, -20.0f);
  EXPECT_GE(bounds.max.y, 20.0f);
}

TEST(SceneFileErrors, MalformedLandscapeNamesTheField) {
  const std::string start = R"({"type": "landscape", "size": [500, 500], "layers": [)";
  expect_input_error(with_objects(start + R"({"cell_size": 10, "density": 0.1, "species": [{"species": "baobab"}]}]})"),
                     {"objects[0].layers[0].species[0].species", "baobab"});
  expect_input_error(with_objects(start + R"({"cell_size": 10, "density": 0.1, "species": [{"species": "oak", "altitude": [5, 1]}]}]})"),
                     {"objects[0].layers[0].species[0].altitude", "smaller"});
  expect_input_error(with_objects(start + R"({"cell_size": 10, "density": 0.1, "species": [{"species": "oak", "slope_max_deg": 95}]}]})"),
                     {"objects[0].layers[0].species[0].slope_max_deg"});
  expect_input_error(with_objects(start + R"({"cell_size": 10, "density": 0.1, "species": [{"species": "oak", "speed": 1}]}]})"),
                     {"objects[0].layers[0].species[0].speed", "unknown key"});
  expect_input_error(with_objects(start + R"({"cell_size": 10, "density": 0.1, "species": [{"file": "tet.obj", "species": "oak"}]}]})"),
                     {"objects[0].layers[0].species[0].file"}, {{"tet.obj", tetrahedron_obj}});
  expect_input_error(with_objects(start + R"({"cell_size": 5000, "density": 1, "species": [{"species": "oak"}]}]})"),
                     {"objects[0]", "layers[0].density", "plants a cell"});
  expect_input_error(with_objects(start + R"({"cell_size": 10, "density": 0.1, "species": []}]})"), {"objects[0].layers[0].species"});
  expect_input_error(with_objects(R"({"type": "landscape", "size": [200000, 500], "layers": []})"), {"objects[0].size"});
  expect_input_error(with_objects(R"({"type": "landscape", "size": [500, 500], "terrain": {"octaves": 40}, "layers": []})"),
                     {"objects[0].terrain.octaves"});
}

// Within 900 m and the band beyond, trees' 20 m cells of 2 × 2 sites and grass's 5 m cells of
// 3 × 3, 1.9 million plants, and room for far blocks' plants, as many as 256 MiB holds, 304 bytes
// each (their tables, GPU records and the cells kept made), and the ground's
// chunks for the camera, 240 bytes a triangle, past 64 MiB; a pool of 16 MiB (--plant-pool)
// holds 91,180 plants.
TEST(SceneFileErrors, ALandscapeWhosePoolPassesTheBudgetIsRefusedSayingWhatItNeeds) {
  std::string big = small_landscape;
  big.replace(big.find("\"radius\": 60"), 12, "\"radius\": 900");
  const InputSource source{"test.json", with_objects(big), [](const std::string&) { return std::string(tetrahedron_obj); }};
  const double mib = 1024.0 * 1024.0;
  try {
    load_scene(source, {64.0 * mib});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("objects[0]"), std::string::npos) << message;
    EXPECT_NE(message.find("memory budget of 0.06 GiB"), std::string::npos) << message;
    const double plants = std::min(114.0 * 114.0 * 4.0 + 452.0 * 452.0 * 9.0 + pointgen::LandscapePool::far_plants,
                                   std::floor(256.0 * mib / 184.0));  // the default --plant-pool
    const LandscapeObject landscape = read_small_landscape();
    const pointgen::GroundChunks ground(landscape.spec, landscape.ground);
    const double triangles = static_cast<double>(ground.chosen({0.0f, 8.0f, 12.0f}).size()) * 2.0 * 32.0 * 32.0;
    const std::size_t at = message.find("would need about ");
    ASSERT_NE(at, std::string::npos) << message;
    const double needs_gib = std::stod(message.substr(at + 17));
    const double expected_gib = (plants * 304.0 + triangles * 240.0) / (1024.0 * mib);
    EXPECT_GE(needs_gib, expected_gib - 0.005) << message;
    EXPECT_LE(needs_gib, expected_gib + 0.01) << message;
  }
  const Scene small_pool = load_scene(source, {256.0 * mib, 16.0 * mib});
  EXPECT_EQ(small_pool.landscapes.at(0).capacity, static_cast<std::size_t>(16.0 * mib / 184.0));
}

TEST(SceneFileErrors, ALandscapeOfCellsTooManyToListIsRefusedBeforeListingThem) {
  // 0.1 m cells of no plants over 100 km: 10^12 keys, 12 TB, where nothing would be made.
  const std::string fine = R"({"type": "landscape", "size": [100000, 100000], "radius": 200000,
      "layers": [{"cell_size": 0.1, "density": 0, "species": [{"species": "meadow grass"}]}]})";
  const auto start = std::chrono::steady_clock::now();
  try {
    load_scene({"test.json", with_objects(fine), [](const std::string&) { return std::nullopt; }}, {4.0 * 1024.0 * 1024.0 * 1024.0});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("objects[0]"), std::string::npos) << message;
    EXPECT_NE(message.find("memory budget of 4.00 GiB"), std::string::npos) << message;
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(SceneFile, EcosystemCrowdTrafficAndSetPiecesLoad) {
  const Scene s = load_objects(R"({"type": "ecosystem", "size": [60, 60], "seed": 3, "plants": [{"species": "birch", "count": 7}],
                                   "animals": [{"kind": "cow", "count": 2}]},
                                  {"type": "crowd", "count": 4, "center": [0, 0, 0], "size": [10, 10]},
                                  {"type": "traffic", "cars": 3, "loops": [[-5, -5, 5, 5]], "aeroplanes": 1},
                                  {"type": "chess", "center": [0, 0, 0]},
                                  {"type": "cathedral", "center": [50, 0, 0]},
                                  {"type": "houses", "from": [0, 0], "to": [0, 40]},
                                  {"type": "lathe", "center": [0, 0, 0], "profile": [[0, 0], [1, 0.5], [0, 1]]},
                                  {"type": "plant", "species": "oak", "positions": [[1, 0, 1], [2, 0, 2]]})");
  ASSERT_EQ(s.animations.size(), 3u);  // the herd, the crowd, the traffic
  std::size_t movers = 0;
  for (const Animation& a : s.animations) movers += a.set.movers.size();
  EXPECT_EQ(movers, 2u + 4u + 4u);
  // terrain 1 + birches 7 + cow parts 2 x 6 + people 4 x 6 + cars 3 x 6 + aeroplane 1 x 2 + board 1 + pieces 32
  // + cathedral 1 + houses 1 + lathe 1 + oaks 2
  EXPECT_EQ(s.instance_count(), 1u + 7u + 12u + 24u + 18u + 2u + 1u + 32u + 1u + 1u + 1u + 2u);
}
}  // namespace
}  // namespace ecoview
