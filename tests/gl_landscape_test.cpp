// A landscape's far blocks drawn a point a plant, against the same plants made whole: they change
// the frame about as much.
#include "app/gl/context.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/scene_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace ecoview {
namespace {

// 1.2 km of gentle ground under meadow grass, seen from 120 m up: its cells made whole within
// `radius` of the eye, the rest in far blocks; no plants at all with `bare`.
std::string meadow(int radius, bool bare = false) {
  const std::string grass = bare ? "0" : "0.2";
  return R"({"camera": {"position": [0, 120, 500], "target": [0, 0, 200], "fov_y_deg": 40, "near": 0.5, "far": 3000},
            "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}],
            "objects": [{"type": "landscape", "size": [1200, 1200], "radius": )" + std::to_string(radius) + R"(, "ground_step": 1,
              "terrain": {"relief": 6, "feature": 300, "valley_depth": 0},
              "layers": [{"cell_size": 8, "density": )" + grass + R"(, "species": [{"species": "meadow grass"}]}]}]})";
}

// How much the frame's plants change the bare ground: per pixel the linear-light difference from
// the bare frame, summed over the frame (it grows with the plants' points until they cover it).
double plants_seen(const Image8& color, const Image8& bare) {
  const auto linear = [](std::uint8_t v) { const double c = v / 255.0; return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  double sum = 0.0;
  for (std::size_t i = 0; i < color.samples.size(); ++i) sum += std::abs(linear(color.samples[i]) - linear(bare.samples[i]));
  return sum;
}

Image8 color_of(const std::string& json, bool points, std::size_t far_plants_at_least = 0) {
  const Scene scene = load_scene({"meadow.json", json, [](const std::string&) { return std::nullopt; }});
  RenderSettings settings;
  settings.width = 480;
  settings.height = 270;
  settings.points = points;
  settings.method = shadow::Method::none;
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  EXPECT_GE(renderer.stats().landscape.far_plants, far_plants_at_least);
  return renderer.frame().read_color();
}

// The meadow's plants all in far blocks, a point each, against every plant made whole and drawn as
// points: they change the bare ground as much within a quarter (844 against 1,042 when written;
// with half the candidates, 445). Both change it about half as much as the grass's polygons seen
// from 120 m (2,096): that is the sampler's count for these blades, made whole or not.
TEST(LandscapeFarBlocks, ChangeTheGroundAsMuchAsTheirPlantsMadeWhole) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const Image8 bare = color_of(meadow(0, true), true);
  const double far = plants_seen(color_of(meadow(0), true, 20000), bare);
  const double whole_points = plants_seen(color_of(meadow(5000), true), bare);
  const double whole_polygons = plants_seen(color_of(meadow(5000), false), bare);
  std::cout << "plants seen: far blocks " << far << ", made whole as points " << whole_points << ", as polygons " << whole_polygons << "\n";
  ASSERT_GT(whole_points, 100.0);
  EXPECT_NEAR(far, whole_points, 0.25 * whole_points);
}

}  // namespace
}  // namespace ecoview
