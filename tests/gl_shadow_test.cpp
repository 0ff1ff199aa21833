// The `shadow` AOV of floating-box scenes against shadows computed from geometry, on every
// headless backend and every light type.
#include "app/capture/png.hpp"
#include "app/gl/context.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/scene_file.hpp"
#include "floating_box.hpp"
#include "shadow_methods.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

namespace ecoview::test {
namespace {

// ECOVIEW_TRUTH_SEED and ECOVIEW_TRUTH_CASES run other random scenes than the default ones, to
// measure agreement beyond what the suite checks (see docs/benchmarks.md); ECOVIEW_TRUTH_DUMP
// names a folder to write each comparison's mismatch image to.
int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : fallback;
}

const char* light_name(shadow::LightType t) {
  return t == shadow::LightType::directional ? "directional" : t == shadow::LightType::point ? "point" : "spot";
}

using Param = std::tuple<std::string, shadow::LightType, shadow::Method>;

class FloatingBoxShadow : public testing::TestWithParam<Param> {};

TEST_P(FloatingBoxShadow, ShadowAovMatchesGeometryAwayFromEdges) {
  const auto& [backend, type, method] = GetParam();
  if (backend == "osmesa" && !osmesa_available()) GTEST_SKIP() << "this build has no OSMesa backend";
  const auto context = create_headless_context(backend);
  pointgen::Random rng(static_cast<std::uint64_t>(env_int("ECOVIEW_TRUTH_SEED", 1) * 10 + static_cast<int>(type)));
  const int cases = env_int("ECOVIEW_TRUTH_CASES", 3);
  for (int i = 0; i < cases; ++i) {
    const FloatingBox s = random_floating_box(rng, type);
    const Scene scene = s.scene();
    Renderer renderer(scene, {640, 480, 2048, method});
    renderer.render(scene.camera, scene.lights[0]);
    const TruthComparison c = compare_with_truth(s, renderer.frame().read_visibility(), 2);
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    if (const char* dump = std::getenv("ECOVIEW_TRUTH_DUMP")) {
      std::ofstream(std::string(dump) + "/" + backend + "_" + light_name(type) + "_" + shadow::technique(method).name + "_" +
                        std::to_string(i) + ".png",
                    std::ios::binary) << encode_png(c.mismatches);
    }
    std::cout << backend << " " << light_name(type) << " " << shadow::technique(method).name << " case " << i << ": " << 100.0 * c.agreement()
              << " % of " << c.lit + c.shadowed << " plane pixels agree; lit " << c.lit_agreeing << "/" << c.lit
              << ", shadowed " << c.shadowed_agreeing << "/" << c.shadowed << " (" << renderer.shadow_setup().description << ")\n";
    EXPECT_GE(c.agreement(), 0.995) << "scene:\n" << s.scene_json();
    // Per class too, so that a frame with no shadows at all cannot pass on the lit majority.
    EXPECT_GE(c.shadowed_agreement(), 0.99) << "scene:\n" << s.scene_json();
    EXPECT_GE(c.lit_agreement(), 0.995) << "scene:\n" << s.scene_json();
    EXPECT_GE(c.shadowed, 300u) << "too little shadow in view to test; scene:\n" << s.scene_json();
    EXPECT_GE(c.lit, 300u) << "too little light in view to test; scene:\n" << s.scene_json();
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllBackendsLightsAndMethods, FloatingBoxShadow,
    testing::Combine(testing::Values("egl", "osmesa"),
                     testing::Values(shadow::LightType::directional, shadow::LightType::point, shadow::LightType::spot),
                     testing::ValuesIn(methods_with_shadows())),
    [](const testing::TestParamInfo<Param>& info) {
      return std::get<0>(info.param) + "_" + light_name(std::get<1>(info.param)) + "_" + test_name(std::get<2>(info.param));
    });

// Pixels whose binary shadow state (visibility < 0.5) differs between two `shadow` AOVs.
std::size_t binary_differences(const Image8& a, const Image8& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) n += (a.samples[i] >= 128) != (b.samples[i] >= 128);
  return n;
}

// The `shadow` AOV of the scene's first view under its first light.
Image8 rendered_visibility(const Scene& scene, shadow::Method method, int map_size) {
  Renderer renderer(scene, {640, 480, map_size, method});
  renderer.render(scene.camera, scene.lights[0]);
  return renderer.frame().read_visibility();
}

// Hybrid shadows are the volumes' where the volumes are counted, and the map is certain of the
// rest: on floating boxes their `shadow` AOVs agree on every pixel but a few, shadow edges
// included, where the uniform map's own edges differ in hundreds.
TEST(HybridShadows, MatchTheVolumesAlongShadowEdgesWhereTheMapDoesNot) {
  const auto context = create_headless_context("egl");
  pointgen::Random rng(5);
  for (shadow::LightType type : {shadow::LightType::directional, shadow::LightType::point, shadow::LightType::spot}) {
    const FloatingBox s = random_floating_box(rng, type);
    const Scene scene = s.scene();
    auto visibility = [&](shadow::Method method) { return rendered_visibility(scene, method, 512); };
    const Image8 volumes = visibility(shadow::Method::volumes);
    EXPECT_LE(binary_differences(visibility(shadow::Method::hybrid), volumes), 20u) << light_name(type);
    EXPECT_GE(binary_differences(visibility(shadow::Method::uniform), volumes), 100u) << light_name(type);
  }
}

// A caster thinner than a texel shadows the plane where no depth sample of the map holds it: the
// uniform map alone misses most of that shadow, and the hybrid must still find it, from the
// caster's silhouette edges, and leave it to the volumes.
TEST(HybridShadows, FindTheShadowOfACasterThinnerThanATexel) {
  const auto context = create_headless_context("egl");
  FloatingBox s;
  s.box_min = {-0.005f, 1.0f, -2.0f};  // a plank 1 cm thick, on edge, a metre over the plane
  s.box_max = {0.005f, 1.3f, 2.0f};
  s.light.type = shadow::LightType::directional;
  s.light.direction = glm::normalize(glm::vec3(0.0f, -1.0f, -0.3f));  // along the plank: its shadow as thin as it is
  s.camera.position = {0.6f, 0.8f, 0.5f};
  s.camera.target = {0.0f, 0.0f, -0.5f};
  s.camera.fov_y_deg = 50.0f;
  s.camera.near = 0.1f;
  s.camera.far = 100.0f;
  const Scene scene = s.scene();
  const int map_size = 64;
  auto against_truth = [&](shadow::Method method) {
    return compare_with_truth(s, rendered_visibility(scene, method, map_size), 1);
  };
  const TruthComparison uniform = against_truth(shadow::Method::uniform), hybrid = against_truth(shadow::Method::hybrid);
  std::cout << "shadowed pixels found: uniform " << uniform.shadowed_agreeing << ", hybrid " << hybrid.shadowed_agreeing
            << " of " << hybrid.shadowed << "; lit found by the hybrid " << hybrid.lit_agreeing << " of " << hybrid.lit << "\n";
  EXPECT_GE(hybrid.shadowed, 300u) << "too little shadow in view to test";
  EXPECT_LE(uniform.shadowed_agreement(), 0.5);
  EXPECT_GE(hybrid.shadowed_agreement(), 0.99);
  EXPECT_GE(hybrid.lit_agreement(), 0.995);
}

// Pixels whose binary shadow state differs between two `shadow` AOVs, counted only where every
// neighbour of the pixel in `exact` has the pixel's own state there (away from its shadow edges).
std::size_t differences_away_from_edges(const Image8& seen, const Image8& exact) {
  auto shadowed = [&](int x, int y) { return exact.samples[static_cast<std::size_t>(y * exact.width + x)] < 128; };
  std::size_t n = 0;
  for (int y = 1; y + 1 < exact.height; ++y) {
    for (int x = 1; x + 1 < exact.width; ++x) {
      bool edge = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) edge |= shadowed(x + dx, y + dy) != shadowed(x, y);
      }
      n += !edge && (seen.samples[static_cast<std::size_t>(y * seen.width + x)] < 128) != shadowed(x, y);
    }
  }
  return n;
}

// The adaptive map's frame of `scene` against the volumes': the pages it asked for and the pixels
// that differ away from the volumes' shadow edges (printed under `name` with all that differ).
struct AgainstVolumes {
  int pages = 0;
  std::size_t away_from_edges = 0;
};
AgainstVolumes adaptive_against_volumes(const Scene& scene, const std::string& name) {
  Renderer adaptive(scene, {640, 480, 512, shadow::Method::adaptive});
  adaptive.render(scene.camera, scene.lights[0]);
  const Image8 seen = adaptive.frame().read_visibility(), volumes = rendered_visibility(scene, shadow::Method::volumes, 512);
  const AgainstVolumes result{adaptive.stats().pages.requested, differences_away_from_edges(seen, volumes)};
  std::cout << name << ": " << result.pages << " pages; pixels that differ from the volumes " << binary_differences(seen, volumes)
            << ", away from their edges " << result.away_from_edges << "\n";
  return result;
}

// The virtual paged map draws each page with a guard of its neighbours' texels, so that its
// filter does not see the page's border: on floating boxes, whose shadows span many pages, its
// `shadow` AOV is the volumes' wherever a pixel is not on the volumes' shadow edge. Seams along
// page borders cross lit and shadowed ground: pages without their guard left 3 wrong pixels there
// under the point and the spot light, with texels of a half pixel or less.
TEST(AdaptiveShadows, MatchTheVolumesAcrossPageBorders) {
  const auto context = create_headless_context("egl");
  pointgen::Random rng(5);
  for (shadow::LightType type : {shadow::LightType::directional, shadow::LightType::point, shadow::LightType::spot}) {
    const FloatingBox s = random_floating_box(rng, type);
    const Scene scene = s.scene();
    const AgainstVolumes adaptive = adaptive_against_volumes(scene, light_name(type));
    EXPECT_GE(adaptive.pages, 8) << light_name(type);
    EXPECT_EQ(adaptive.away_from_edges, 0u) << light_name(type);
  }
}

// On a plane 2 km wide, a camera at eye height asks for the finest levels near it and for coarse
// ones at posts far off; a telephoto camera asks for fine levels far off, beyond the windows a frame
// addresses of them (shadow::VirtualMap::window), and gets the finest level its windows hold. Both
// see the volumes' shadows wherever a pixel is not on the volumes' shadow edge.
TEST(AdaptiveShadows, MatchTheVolumesNearTheCameraAndFarFromItOnAWidePlane) {
  const auto context = create_headless_context("egl");
  std::string posts;
  for (const float z : {-4.0f, -7.0f, -12.0f, -60.0f, -150.0f, -400.0f}) {
    const float half = 0.1f - z * 0.01f;
    for (const float x : {-3.0f, 0.5f, 4.0f}) {
      const float cx = x * (1.0f - z * 0.05f);
      posts += R"(, {"type": "box", "min": [)" + std::to_string(cx - half) + ", 0, " + std::to_string(z - half) + "], \"max\": [" +
               std::to_string(cx + half) + ", " + std::to_string(8.0f * half) + ", " + std::to_string(z + half) + "]}";
    }
  }
  const shadow::VirtualMap map;
  ASSERT_GT(map.pages_per_side(0), map.window);  // the finest levels are windowed
  for (const std::string camera : {R"({"position": [0, 1.7, 0], "target": [0, 0.8, -30], "fov_y_deg": 60, "near": 0.1, "far": 1500})",
                                   R"({"position": [0, 1.7, 0], "target": [3, 0.5, -150], "fov_y_deg": 4, "near": 1, "far": 1500})"}) {
    const std::string json = R"({"camera": )" + camera + R"(, "lights": [{"type": "directional", "direction": [0.5, -0.6, -0.4]}],
      "objects": [{"type": "plane", "center": [0, 0, 0], "size": [2000, 2000]})" + posts + "]}";
    const Scene scene = load_scene({"wide.json", json, [](const std::string&) { return std::nullopt; }});
    const AgainstVolumes adaptive = adaptive_against_volumes(scene, "fov " + std::to_string(scene.camera.fov_y_deg));
    EXPECT_GE(adaptive.pages, 8);
    EXPECT_EQ(adaptive.away_from_edges, 0u);
  }
}

// A still camera keeps the pages it drew: the same frame again draws none, and a later one draws
// again only the pages its moving people and cars were or are over, yet shows what a renderer that
// draws every page shows.
TEST(AdaptiveShadows, AStillCameraDrawsAgainOnlyThePagesOfMovingCasters) {
  const auto context = create_headless_context("egl");
  const Scene scene = load_scene(open_input("street", "scenes"));
  Renderer renderer(scene, {320, 180, 512, shadow::Method::adaptive});
  renderer.render(scene.camera, scene.lights[0], 0.0);
  const FrameStats::Pages first = renderer.stats().pages;
  renderer.render(scene.camera, scene.lights[0], 0.0);
  const FrameStats::Pages again = renderer.stats().pages;
  renderer.render(scene.camera, scene.lights[0], 0.5);
  const FrameStats::Pages later = renderer.stats().pages;
  std::cout << "pages asked for " << first.requested << ", drawn " << first.drawn << "; the same frame: " << again.drawn
            << " drawn; half a second later: " << later.drawn << " drawn, " << later.cached << " kept\n";
  EXPECT_EQ(first.drawn, first.requested);
  EXPECT_EQ(again.drawn, 0);
  EXPECT_EQ(again.cached, again.requested);
  EXPECT_GT(later.drawn, 0);
  EXPECT_GT(later.cached, later.requested / 4);
  Renderer fresh(scene, {320, 180, 512, shadow::Method::adaptive});
  fresh.render(scene.camera, scene.lights[0], 0.5);
  EXPECT_LE(binary_differences(renderer.frame().read_visibility(), fresh.frame().read_visibility()), 20u);
}

// A scene of `plants` (plant_grid_json) and a `plane` object under a directional light, seen by
// `camera` (each in the scene format's JSON).
Scene plants_on_a_plane(const std::string& camera, const std::string& light_direction, const std::string& plane,
                        const std::string& plants) {
  const std::string json = R"({"camera": )" + camera + R"(, "lights": [{"type": "directional", "direction": )" + light_direction +
                           R"(}], "objects": [)" + plane + ", " + plants + "]}";
  return load_scene({"plants.json", json, [](const std::string&) { return std::nullopt; }});
}

// Point splats cast no volumes, so the hybrid's map keeps them in layers of their own and decides
// their shadows alone; the volumes decide only near the polygons' edges. Under a grove, far trees
// as points and near ones as polygons, the hybrid errs against the ray-traced reference (plants as
// meshes) no more than the uniform map it starts from: where the points' shadow edges went to the
// volumes, they were lit (8.5 % of pixels wrong against the map's 5.4 %).
TEST(HybridShadows, LeaveThePointCastersShadowsToTheMap) {
  const auto context = create_headless_context("egl");
  const Scene scene = plants_on_a_plane(R"({"position": [0, 12, 0], "target": [0, 0, -60], "fov_y_deg": 50, "near": 0.5, "far": 400})",
                                        "[0.5, -0.6, -0.4]", R"({"type": "plane", "center": [0, 0, -100], "size": [300, 300]})",
                                        plant_grid_json("beech", 24, 6, -40, 16, -40, -20));
  auto wrong_share = [&](shadow::Method method) {
    Renderer renderer(scene, {640, 360, 1024, method});
    renderer.render(scene.camera, scene.lights[0]);
    const Image8 seen = renderer.frame().read_visibility();
    return static_cast<double>(binary_differences(seen, renderer.exact_visibility())) / static_cast<double>(seen.samples.size());
  };
  const double uniform = wrong_share(shadow::Method::uniform), hybrid = wrong_share(shadow::Method::hybrid);
  std::cout << "wrong pixels: uniform " << 100.0 * uniform << " %, hybrid " << 100.0 * hybrid << " %\n";
  EXPECT_GE(uniform, 0.005);  // the grove's shadows are in view, and a map errs along them
  EXPECT_LE(hybrid, 1.1 * uniform);
}

// The GPU sampler lists the plants it draws as polygons on the GPU, apart from the scene's instance
// tables; the shadow volumes and the silhouette map draw those lists too. Under a row of plants near
// enough to be drawn as polygons, the volumes' shadows are the ray-traced reference's (plants as
// meshes) but for a few edge pixels, with the GPU's choice as with the CPU's; without the plants'
// volumes they would miss the plants' shadows whole. The silhouette map with the GPU's choice
// agrees with the CPU's about as well.
TEST(GpuSampledPlants, CastShadowVolumesAndSilhouettes) {
  const auto context = create_headless_context("egl");
  const Scene scene = plants_on_a_plane(R"({"position": [0, 3, 8], "target": [0, 1, -4], "fov_y_deg": 50, "near": 0.2, "far": 200})",
                                        "[0.6, -0.7, -0.3]", R"({"type": "plane", "center": [0, 0, -20], "size": [80, 80]})",
                                        plant_grid_json("beech", 3, 3, -4, 4, -4, 0));
  auto visibility = [&](shadow::Method method, bool gpu_sampler, Image8* exact) {
    RenderSettings settings{640, 360, 1024, method};
    settings.gpu_sampler = gpu_sampler;
    Renderer renderer(scene, settings);
    renderer.render(scene.camera, scene.lights[0]);
    if (exact != nullptr) *exact = renderer.exact_visibility();
    return renderer.frame().read_visibility();
  };
  Image8 exact;
  const Image8 volumes_gpu = visibility(shadow::Method::volumes, true, &exact);
  const Image8 volumes_cpu = visibility(shadow::Method::volumes, false, nullptr);
  const Image8 silhouette_gpu = visibility(shadow::Method::silhouette, true, nullptr);
  const Image8 silhouette_cpu = visibility(shadow::Method::silhouette, false, nullptr);
  std::size_t shadowed = 0;
  for (std::uint8_t v : exact.samples) shadowed += v < 128;
  std::cout << "shadowed " << shadowed << ", volumes wrong: gpu " << binary_differences(volumes_gpu, exact) << ", cpu "
            << binary_differences(volumes_cpu, exact) << "; silhouette gpu against cpu " << binary_differences(silhouette_gpu, silhouette_cpu)
            << ", against exact: gpu " << binary_differences(silhouette_gpu, exact) << ", cpu " << binary_differences(silhouette_cpu, exact) << "\n";
  EXPECT_GE(shadowed, exact.samples.size() / 20);  // the plants' shadows are in view
  EXPECT_LE(binary_differences(volumes_gpu, exact), shadowed / 50);
  EXPECT_LE(binary_differences(volumes_cpu, exact), shadowed / 50);
  EXPECT_LE(binary_differences(silhouette_gpu, silhouette_cpu), shadowed / 50);
}

// A silhouette map moves a shadow's edges from the texels' staircase onto the casters' silhouette:
// on floating boxes under a coarse map, its plane pixels that disagree with the geometry's shadow,
// edges included, are at most half those of the same map filtered. So in the pages of the adaptive
// map, whose texels are finer than the pixels: fewer pixels disagree to begin with (a few under
// the directional light), so its texels must show over the three lights together.
TEST(SilhouetteMaps, HalveTheMapsDisagreementWithGeometryAlongShadowEdges) {
  const auto context = create_headless_context("egl");
  pointgen::Random rng(9);
  struct Pair {
    shadow::Method filtered, silhouette;
    std::size_t at_least;  // pixels the filtered map gets wrong under the three lights: its texels show
    std::size_t by_map = 0;
  };
  std::vector<Pair> pairs{{shadow::Method::uniform, shadow::Method::silhouette, 300},
                          {shadow::Method::psm, shadow::Method::psm_silhouette, 300},
                          {shadow::Method::adaptive, shadow::Method::adaptive_silhouette, 100}};
  for (shadow::LightType type : {shadow::LightType::directional, shadow::LightType::point, shadow::LightType::spot}) {
    const FloatingBox s = random_floating_box(rng, type);
    const Scene scene = s.scene();
    auto disagreeing = [&](shadow::Method method) {
      const TruthComparison c = compare_with_truth(s, rendered_visibility(scene, method, 256), 0);
      return c.lit + c.shadowed - c.lit_agreeing - c.shadowed_agreeing;
    };
    for (Pair& pair : pairs) {
      const std::size_t by_map = disagreeing(pair.filtered), by_silhouettes = disagreeing(pair.silhouette);
      std::cout << light_name(type) << " " << shadow::technique(pair.filtered).name << ": " << by_map << " pixels disagree, with silhouettes "
                << by_silhouettes << "\n";
      pair.by_map += by_map;
      EXPECT_LE(2 * by_silhouettes, by_map) << light_name(type) << " " << shadow::technique(pair.silhouette).name;
    }
  }
  for (const Pair& pair : pairs) EXPECT_GE(pair.by_map, pair.at_least) << shadow::technique(pair.filtered).name;
}

// A low point light whose receivers lie mostly on one side of it: IPSM takes two paraboloids
// along a tilted axis, so their seam crosses the plane, and the box stands between the light and
// the camera, so its shadow falls into the back map. Without the clip beyond 120° in the
// paraboloid pass, the piece of plane around the back map's pole covered that whole map and half
// the lit plane read as shadowed.
TEST(ParaboloidSeam, AShadowInTheBackParaboloidMatchesGeometry) {
  const auto context = create_headless_context("egl");
  FloatingBox s;
  s.box_min = {-4.5f, 0.6f, -1.0f};
  s.box_max = {-3.5f, 1.6f, 1.0f};
  s.light = {shadow::LightType::point, {0.0f, 3.0f, 0.0f}, {0, -1, 0}, 30};
  s.camera.position = {-16.0f, 7.0f, 4.0f};
  s.camera.target = {2.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 60.0f;
  s.camera.near = 0.1f;
  s.camera.far = 100.0f;
  const Scene scene = s.scene();
  Renderer renderer(scene, {640, 480, 2048, shadow::Method::ipsm});
  renderer.render(scene.camera, scene.lights[0]);
  const shadow::ShadowSetup& setup = renderer.shadow_setup();
  ASSERT_EQ(setup.selection, shadow::ViewSelection::hemispheres) << setup.description;
  const glm::vec3 shadow_centre(-6.5f, 0.0f, 0.0f);
  ASSERT_GT((setup.views[0].view * glm::vec4(shadow_centre, 1.0f)).z, 0.0f) << "the shadow is not in the back map";
  const TruthComparison c = compare_with_truth(s, renderer.frame().read_visibility(), 2);
  EXPECT_GE(c.lit_agreement(), 0.995);
  EXPECT_GE(c.shadowed_agreement(), 0.99);
  EXPECT_GE(c.shadowed, 300u);
}

// ecoview view changes the method and the map size of a running renderer: its next frames are
// those of a renderer made with the new settings.
TEST(RendererChange, FramesAfterAChangeAreThoseOfAFreshRenderer) {
  const auto context = create_headless_context("egl");
  pointgen::Random rng(77);
  const FloatingBox s = random_floating_box(rng, shadow::LightType::directional);
  const Scene scene = s.scene();
  Renderer changed(scene, {320, 240, 1024, shadow::Method::uniform});
  changed.render(scene.camera, scene.lights[0]);
  // Method alone, size alone, both, and back to methods that keep state between frames.
  for (const auto& [method, size] : {std::pair{shadow::Method::psm, 1024}, std::pair{shadow::Method::psm, 2048},
                                     std::pair{shadow::Method::volumes, 2048}, std::pair{shadow::Method::reference, 2048},
                                     std::pair{shadow::Method::cascades, 512},
                                     std::pair{shadow::Method::automatic, 512}, std::pair{shadow::Method::lispsm, 512},
                                     std::pair{shadow::Method::hybrid, 1024}, std::pair{shadow::Method::psm_silhouette, 512},
                                     std::pair{shadow::Method::silhouette, 512}}) {
    changed.change(method, size, 3.0f);
    changed.render(scene.camera, scene.lights[0]);
    Renderer fresh(scene, {320, 240, size, method, true, 3.0f});
    fresh.render(scene.camera, scene.lights[0]);
    EXPECT_EQ(changed.frame().read_color().samples, fresh.frame().read_color().samples) << shadow::technique(method).name;
    EXPECT_EQ(changed.shadow_setup().description, fresh.shadow_setup().description);
  }
}

// The shadow map's depth at its centre, a window depth 0..1, of a ground plane under a light
// straight above: the plane faces the map, no slope, so the bias moves it by the constant alone.
double flat_ground_map_depth(ShadowDepth format, float constant_bias) {
  const Scene scene = load_scene({"ground.json", R"({"camera": {"position": [0, 10, 20], "target": [0, 0, 0]},
      "lights": [{"type": "directional", "direction": [0, -1, 0]}],
      "objects": [{"type": "plane", "center": [0, 0, 0], "size": [40, 40]}]})",
                                  [](const std::string&) { return std::nullopt; }});
  RenderSettings settings{320, 240, 256, shadow::Method::uniform};
  settings.shadow_bias = {0.0f, constant_bias};
  settings.shadow_depth = format;
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  return renderer.shadow_map().read_layer(0).at(128, 128);
}

// --bias-constant: polygon offset units, which for a float depth buffer are steps of 2^(e - 23)
// at a depth of exponent e (the GL specification, 14.6.5).
TEST(ShadowBias, TheConstantBiasMovesAFlatCasterByThatManyStepsOfItsDepth) {
  const auto context = create_headless_context("egl");
  auto centre_depth = [](float constant) { return static_cast<float>(flat_ground_map_depth(ShadowDepth::float32, constant)); };
  const float unbiased = centre_depth(0.0f);
  ASSERT_GT(unbiased, 0.0f);
  ASSERT_LT(unbiased, 1.0f);
  const float step = std::ldexp(1.0f, std::ilogb(unbiased) - 23);
  EXPECT_NEAR(centre_depth(1000.0f) - unbiased, 1000.0f * step, 2.0f * step);
  EXPECT_NEAR(centre_depth(100000.0f) - unbiased, 100000.0f * step, 2.0f * step);
}

// --shadow-depth 16 and 24: fixed point, so every depth the map holds is a whole number of steps
// of 1 / (2^bits - 1), and the constant bias moves the same flat caster in proportion to it.
TEST(ShadowDepthFormat, FixedPointMapsHoldWholeStepsAndTheBiasCountsInThem) {
  const auto context = create_headless_context("egl");
  for (const auto& [format, bits] : {std::pair{ShadowDepth::fixed16, 16}, std::pair{ShadowDepth::fixed24, 24}}) {
    const double steps = std::ldexp(1.0, bits) - 1.0;
    auto centre_depth = [&, format = format](float constant) { return flat_ground_map_depth(format, constant) * steps; };
    const double unbiased = centre_depth(0.0f);
    ASSERT_GT(unbiased, 1.0) << bits;
    ASSERT_LT(unbiased, steps - 1.0) << bits;
    // Read back as float: exact for 16 bits, within float rounding for 24.
    EXPECT_NEAR(unbiased, std::round(unbiased), bits == 16 ? 1e-3 : 1.0) << bits;
    // The offset unit r is the format's smallest resolvable difference, which the GL lets an
    // implementation choose: Mesa takes two steps on fixed-point formats, one on float.
    const double r = (centre_depth(1000.0f) - unbiased) / 1000.0;
    EXPECT_GE(r, 0.99) << bits;
    EXPECT_LE(r, 2.01) << bits;
    EXPECT_NEAR(centre_depth(100.0f) - unbiased, 100.0 * r, 2.0) << bits;
  }
}

// The frame's nearest depth, reduced on the GPU in blocks of 8 × 8 pixels, is the least positive
// depth of its depth AOV. The camera looks at a wall obliquely, so the wall comes nearest along
// the image's last column, which a size of 331 pixels puts in blocks partly outside the image.
TEST(FrameNearestDepth, IsTheLeastDepthOfTheFrame) {
  const auto context = create_headless_context("egl");
  const Scene scene = load_scene({"wall.json", R"({"camera": {"position": [20, 5, 15], "target": [0, 5, 0], "fov_y_deg": 50},
    "lights": [{"type": "directional", "direction": [0.3, -1, -0.2]}],
    "objects": [{"type": "box", "min": [-100, -50, -1], "max": [100, 50, 0]}]})",
                                  [](const std::string&) { return std::nullopt; }});
  Renderer renderer(scene, {331, 203, 512, shadow::Method::uniform});
  renderer.render(scene.camera, scene.lights[0]);
  const Image<float> depth = renderer.frame().read_depth();
  float least = 0.0f;
  int least_column = -1;
  for (std::size_t i = 0; i < depth.samples.size(); ++i) {
    const float d = depth.samples[i];
    if (d > 0.0f && (least == 0.0f || d < least)) {
      least = d;
      least_column = static_cast<int>(i % 331);
    }
  }
  ASSERT_EQ(least_column, 330);  // the scene is as described
  EXPECT_EQ(renderer.frame().nearest_depth(), least);
}

}  // namespace
}  // namespace ecoview::test
