// Point rendering against the polygon rendering of the same plants: the points must cover what
// the polygons cover, and stand where they stand.
#include "app/bench/density_figures.hpp"
#include "app/gl/context.hpp"
#include "depth_coverage.hpp"
#include "test_support.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/scene_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <sstream>

namespace ecoview {
namespace {

// A grove of plants `nearest` to `nearest` + 80 m away against the sky, so every covered pixel is
// a plant.
std::string grove(int nearest = 40, const std::string& species = "beech") {
  std::ostringstream s;
  s << R"({"camera": {"position": [0, 8, 0], "target": [0, 6, -60], "fov_y_deg": 40, "near": 0.5, "far": 400},
          "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}],
          "objects": [)" << test::plant_grid_json(species, 40, 8, -49, 14, static_cast<float>(-nearest), -20) << "]}";
  return s.str();
}

// The scene at 480 × 270 with `settings`, rendered once with every plant as polygons and once with
// points.
struct PolygonsAndPoints {
  std::unique_ptr<Renderer> polygons, points;
};
PolygonsAndPoints render_both_ways(const Scene& scene, RenderSettings settings) {
  settings.width = 480;
  settings.height = 270;
  PolygonsAndPoints both;
  settings.points = false;
  both.polygons = std::make_unique<Renderer>(scene, settings);
  both.polygons->render(scene.camera, scene.lights[0]);
  settings.points = true;
  both.points = std::make_unique<Renderer>(scene, settings);
  both.points->render(scene.camera, scene.lights[0]);
  return both;
}

// The grove rendered at the default density as polygons and as points.
class PointRendering : public testing::Test {
 protected:
  void SetUp() override {
    PolygonsAndPoints both = render_both_ways(scene, {});
    polygons = std::move(both.polygons);
    points = std::move(both.points);
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }

  std::unique_ptr<GlContext> context = create_headless_context("egl");
  Scene scene = load_scene({"grove.json", grove(), [](const std::string&) { return std::nullopt; }});
  std::unique_ptr<Renderer> polygons, points;
};

TEST_F(PointRendering, PointsCoverWhatPolygonsCoverAtTheDefaultDensity) {
  EXPECT_GT(points->stats().points, 10000u) << "the far trees should be points";
  EXPECT_LT(points->stats().triangles, polygons->stats().triangles / 2);
  const Coverage c = compare(polygons->frame().read_depth(), points->frame().read_depth());
  ASSERT_GT(c.polygons, 20000u);
  const double holes = 1.0 - static_cast<double>(c.both) / static_cast<double>(c.polygons);
  const double outside = static_cast<double>(c.points - c.both) / static_cast<double>(c.polygons);
  std::cout << "holes " << 100.0 * holes << " %, points outside the polygons " << 100.0 * outside << " %\n";
  EXPECT_LT(holes, 0.05);
  // A point near a triangle edge lands in a pixel whose centre the triangle misses, and a 2-pixel
  // splat reaches one pixel further: around thin twigs and leaf edges that is about a tenth.
  EXPECT_LT(outside, 0.15) << "points must lie on the surfaces";
}

TEST_F(PointRendering, PointDepthsMatchPolygonDepths) {
  const Image<float> a = polygons->frame().read_depth(), b = points->frame().read_depth();
  // Where both cover a pixel, the nearest point mostly lies on the front surface seen there: within
  // a quarter metre (a pixel is 0.1-0.3 m wide at 40-120 m). Points anywhere in the crowns, metres
  // deep, would miss that. The rest are leaf edges, where a splat reaches past the front leaf.
  std::size_t both = 0, close = 0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    if (a.samples[i] < 0.0f || b.samples[i] < 0.0f) continue;
    ++both;
    close += std::abs(a.samples[i] - b.samples[i]) < 0.25f;
  }
  EXPECT_GT(static_cast<double>(close) / static_cast<double>(both), 0.85);
}

// How much the frame's plants hide the sky behind them: per pixel the linear-light difference
// from the sky (the top-left pixel, which no plant reaches), summed over the frame.
double sky_hidden(const Image8& color) {
  const auto linear = [](std::uint8_t v) { const double c = v / 255.0; return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  double sum = 0.0;
  for (std::size_t i = 0; i < color.samples.size(); ++i) sum += std::abs(linear(color.samples[i]) - linear(color.samples[i % 3]));
  return sum;
}

TEST(PointCoverage, FarBirchesOfPointsHideAsMuchOfTheSkyAsTheirPolygons) {
  // Birches 80-160 m away, their twigs and leaves finer than a pixel. Polygons at one sample a
  // pixel cover a pixel's centre as often as their surface covers pixels: over thousands of pixels
  // their sum is the crowns' true cover. Points drawn as whole 2 × 2 splats hid 1.6 times as much;
  // covering each pixel by the image area of its points leaves 1.16 (a splat still spreads a twig
  // over two pixels' width).
  std::unique_ptr<GlContext> context = create_headless_context("egl");
  const Scene scene = load_scene({"grove.json", grove(80, "birch"), [](const std::string&) { return std::nullopt; }});
  const PolygonsAndPoints both = render_both_ways(scene, {});
  ASSERT_GT(both.points->stats().points, 50000u) << "the birches should be points";
  const double ratio = sky_hidden(both.points->frame().read_color()) / sky_hidden(both.polygons->frame().read_color());
  std::cout << "sky hidden by points / polygons: " << ratio << "\n";
  EXPECT_GT(ratio, 0.8);
  EXPECT_LT(ratio, 1.25);
}

// A crown of 3,000 leaves, 0.3 m squares in random places and turns within 2 m of (0, 3, 0), as
// the OBJ text a user's tree could be.
std::string leafy_crown_obj() {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::ostringstream obj;
  for (int leaf = 0; leaf < 3000; ++leaf) {
    const glm::vec3 center = glm::vec3(0, 3, 0) + 2.0f * glm::vec3(unit(random), unit(random), unit(random));
    const glm::vec3 a = 0.15f * glm::normalize(glm::vec3(unit(random), unit(random), unit(random)) + glm::vec3(0.01f));
    const glm::vec3 b = 0.15f * glm::normalize(glm::cross(a, glm::vec3(unit(random), unit(random), unit(random)) + glm::vec3(0.01f)));
    for (const glm::vec3& corner : {center - a - b, center + a - b, center + a + b, center - a + b}) {
      obj << "v " << corner.x << " " << corner.y << " " << corner.z << "\n";
    }
    const int v = 4 * leaf + 1;
    obj << "f " << v << " " << v + 1 << " " << v + 2 << "\nf " << v << " " << v + 2 << " " << v + 3 << "\n";
  }
  return obj.str();
}

// A mesh object with "points": true is a species like the built-in plants: the sampler draws its
// far instances as points and its near ones as polygons. Forty crowns 100-180 m away are all
// points; one 6 m from the camera is all polygons; the same file without "points" is polygons at
// any distance.
TEST(MeshSpecies, AMeshFromAFileIsPointsFarAndPolygonsNear) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const std::string crown = leafy_crown_obj();
  const auto scene_of = [&](const std::string& positions, bool points) {
    std::string transforms;
    std::istringstream list(positions);
    for (float x, z; list >> x >> z;) {
      transforms += std::string(transforms.empty() ? "" : ", ") + "[1,0,0,0, 0,1,0,0, 0,0,1,0, " + std::to_string(x) +
                    ",0," + std::to_string(z) + ",1]";
    }
    const std::string json = R"({"camera": {"position": [0, 3, 0], "target": [0, 3, -60], "fov_y_deg": 40, "near": 0.5, "far": 400},
        "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}],
        "objects": [{"type": "mesh", "file": "crown.obj", "points": )" + std::string(points ? "true" : "false") +
                             R"(, "transforms": [)" + transforms + "]}]}";
    return load_scene({"crowns.json", json, [&](const std::string& path) -> std::optional<std::string> {
                         if (path == "crown.obj") return crown;
                         return std::nullopt;
                       }});
  };
  std::string far, near = "0 -6";
  for (int i = 0; i < 40; ++i) far += std::to_string((i % 8) * 12 - 42) + " " + std::to_string(-100 - (i / 8) * 20) + " ";
  RenderSettings settings;
  settings.width = 480;
  settings.height = 270;
  const auto frame_stats = [&](const Scene& scene) {
    Renderer renderer(scene, settings);
    renderer.render(scene.camera, scene.lights[0]);
    return renderer.stats();
  };
  const std::size_t crown_triangles = 6000;
  const FrameStats far_points = frame_stats(scene_of(far, true));
  EXPECT_GT(far_points.points, 10000u) << "the far crowns should be points";
  EXPECT_EQ(far_points.triangles, 0u);
  EXPECT_GT(far_points.shadow_points, 0u) << "and cast their shadows as points";
  const FrameStats near_polygons = frame_stats(scene_of(near, true));
  EXPECT_EQ(near_polygons.points, 0u) << "the near crown should be polygons";
  EXPECT_EQ(near_polygons.triangles, crown_triangles);
  const FrameStats far_polygons = frame_stats(scene_of(far, false));
  EXPECT_EQ(far_polygons.points, 0u) << "without \"points\" a mesh is always polygons";
  EXPECT_EQ(far_polygons.triangles, 40 * crown_triangles);
}

// With every plant as polygons, plants out of view are not drawn and those in view are: five
// beeches straight ahead give each of their triangles; three more behind the camera change neither
// the triangles nor the image (without shadows: the larger scene would fit the map differently).
TEST(PolygonMode, PlantsOutOfViewAreNotDrawn) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const std::string ahead = R"({"camera": {"position": [0, 8, 0], "target": [0, 6, -60], "fov_y_deg": 40, "near": 0.5, "far": 400},
      "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}],
      "objects": [{"type": "plant", "species": "beech", "positions": [[0, 0, -40], [0, 0, -60], [0, 0, -80], [0, 0, -100], [0, 0, -120]]})";
  const std::string behind = R"(, {"type": "plant", "species": "beech", "positions": [[0, 0, 60], [20, 0, 80], [-30, 0, 100]]})";
  RenderSettings settings;
  settings.width = 320;
  settings.height = 180;
  settings.points = false;
  settings.method = shadow::Method::none;
  Image8 color[2];
  std::size_t triangles[2], five_beeches = 0;
  int i = 0;
  for (const std::string& json : {ahead + "]}", ahead + behind + "]}"}) {
    const Scene scene = load_scene({"grove.json", json, [](const std::string&) { return std::nullopt; }});
    if (i == 0) five_beeches = 5 * scene.meshes[scene.groups.front().mesh].triangle_count();
    Renderer renderer(scene, settings);
    renderer.render(scene.camera, scene.lights[0]);
    color[i] = renderer.frame().read_color();
    triangles[i++] = renderer.stats().triangles;
  }
  EXPECT_GT(five_beeches, 0u);
  EXPECT_EQ(triangles[0], five_beeches);
  EXPECT_EQ(triangles[1], five_beeches);
  EXPECT_EQ(color[1].samples, color[0].samples);
}

// ...but a plant out of the camera's view still casts its shadow into it: an 18 m beech 35 m to
// the left of a camera looking down a plane, under a low sun from the left (26.6° up), throws its
// shadow some 36 m to the right, across the view. The frame draws the same triangles with and
// without it; the shadow map must draw it.
TEST(PolygonMode, APlantOutOfViewCastsItsShadowIntoIt) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const std::string start = R"({"camera": {"position": [0, 2, 0], "target": [0, 0, -20], "fov_y_deg": 40, "near": 0.5, "far": 200},
      "lights": [{"type": "directional", "direction": [1, -0.5, 0]}],
      "objects": [{"type": "plane", "center": [0, 0, -20], "size": [200, 200]})";
  RenderSettings settings;
  settings.width = 320;
  settings.height = 180;
  settings.points = false;
  std::size_t shadowed[2], triangles[2];
  int i = 0;
  for (const std::string& json : {start + "]}", start + R"(, {"type": "plant", "species": "beech", "positions": [[-35, 0, -20]]}]})"}) {
    const Scene scene = load_scene({"beech.json", json, [](const std::string&) { return std::nullopt; }});
    Renderer renderer(scene, settings);
    renderer.render(scene.camera, scene.lights[0]);
    const Image8 visibility = renderer.frame().read_visibility();
    shadowed[i] = static_cast<std::size_t>(std::count_if(visibility.samples.begin(), visibility.samples.end(), [](std::uint8_t v) { return v < 128; }));
    triangles[i++] = renderer.stats().triangles;
  }
  EXPECT_EQ(triangles[1], triangles[0]) << "the beech is out of the camera's view";
  EXPECT_EQ(shadowed[0], 0u);
  EXPECT_GT(shadowed[1], 500u) << "its shadow should lie across the view";
}

// View-adaptive: the sampler gives every surface about k points per pixel of its image, so the
// points on the surface seen in a pixel do not depend on its distance (docs/point_density.md).
// Cacti, whose stems are solid: far foliage finer than a pixel covers the pixels it is counted in
// only in part, so its points per covered pixel fall with distance however right the count.
TEST(PointDensity, PointsPerPixelOfTheSeenSurfaceDoNotFollowDistance) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const Scene scene = load_scene({"grove.json", grove(80, "saguaro"), [](const std::string&) { return std::nullopt; }});
  RenderSettings settings;
  settings.k = 1.5f;  // low enough that every cactus is points
  PolygonsAndPoints both = render_both_ways(scene, settings);
  const Renderer& polygons = *both.polygons;
  Renderer& points = *both.points;
  ASSERT_EQ(points.stats().triangles, 0u) << "every cactus should be points";
  DensityRenders renders;
  renders.polygons = {polygons.frame().read_color(), polygons.frame().read_depth()};
  renders.points = {points.frame().read_color(), points.frame().read_depth()};
  renders.occluders = renders.polygons;
  std::fill(renders.occluders.depth.samples.begin(), renders.occluders.depth.samples.end(), -1.0f);
  const DensityFigures f = density_figures(renders, points.count_points_on(renders.polygons.depth));
  std::cout << "points per pixel of the seen surface: " << f.pts_per_px_near << " / " << f.pts_per_px_middle << " / "
            << f.pts_per_px_far << " (" << f.third_depths[0] << " to " << f.third_depths[3] << " m)\n";
  ASSERT_GT(f.third_depths[3], 1.5f * f.third_depths[0]);
  EXPECT_GT(f.pts_per_px, 0.5 * settings.k);
  EXPECT_LT(f.pts_per_px, 4.0 * settings.k);
  EXPECT_NEAR(f.pts_per_px_far / f.pts_per_px_near, 1.0, 0.25);
}

// The CPU sampler's caster culling (pointgen::ReceiverMask) skips casters by where the last frame
// saw surfaces: the shadows the camera sees stay as they were, with fewer shadow points. A stand
// of trees and bushes seen from its edge, where most of it is hidden behind its first rows.
TEST(CasterCulling, KeepsTheShadowsTheCameraSees) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const Scene scene = load_scene({"stand.json", R"({
      "camera": {"position": [0, 10, 75], "target": [0, 4, 20], "fov_y_deg": 50, "near": 0.5, "far": 300},
      "lights": [{"type": "directional", "direction": [0.5, -0.7, -0.3]}],
      "objects": [{"type": "ecosystem", "seed": 5, "size": [100, 100], "terrain": {"relief": 0.5, "resolution": 16},
                   "plants": [{"species": "oak", "count": 800}, {"species": "hazel", "count": 800}]}]})",
                                  [](const std::string&) { return std::nullopt; }});
  for (const shadow::Method method : {shadow::Method::uniform, shadow::Method::psm, shadow::Method::cascades}) {
    RenderSettings settings;
    settings.width = 480;
    settings.height = 270;
    settings.shadow_size = 1024;
    settings.method = method;
    settings.gpu_sampler = false;  // the CPU sampler's culling (the GPU sampler's: gl_sampler_test.cpp)
    Renderer culled(scene, settings);
    settings.cull_casters = false;
    Renderer every_caster(scene, settings);
    culled.render(scene.camera, scene.lights[0]);
    every_caster.render(scene.camera, scene.lights[0]);
    const Image8 a = culled.frame().read_visibility(), b = every_caster.frame().read_visibility();
    std::size_t changed = 0, shadowed = 0;
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
      changed += a.samples[i] != b.samples[i];
      shadowed += b.samples[i] < 128;
    }
    const double changed_share = static_cast<double>(changed) / static_cast<double>(a.samples.size());
    std::cout << shadow::technique(method).name << ": shadow points " << culled.stats().shadow_points << " of "
              << every_caster.stats().shadow_points << ", " << changed << " pixels changed, " << shadowed << " shadowed\n";
    EXPECT_GT(shadowed, a.samples.size() / 20) << shadow::technique(method).name;
    EXPECT_LT(culled.stats().shadow_points, every_caster.stats().shadow_points * 4 / 5) << shadow::technique(method).name;
    EXPECT_LT(changed_share, 0.005) << shadow::technique(method).name;
  }
}

}  // namespace
}  // namespace ecoview
