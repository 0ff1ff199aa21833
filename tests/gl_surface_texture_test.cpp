// Textured, alpha-masked glTF polygons in the frame and in every shadow map, against the texture
// and the mask the test wrote (textured_card.hpp) and geometry the test computes.
#include "app/gl/context.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/scene_file.hpp"
#include "shadow_methods.hpp"
#include "textured_card.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <iostream>
#include <optional>

namespace ecoview {
namespace {

Scene card_scene(const std::string& camera, const std::string& light, const std::string& card_transform, bool ground,
                 int mag_filter = 9729) {
  const TexturedCard card = textured_card("MASK", mag_filter);
  const std::string json = R"({"camera": )" + camera + R"(, "lights": [)" + light + R"(], "objects": [)" +
                           (ground ? R"({"type": "plane", "center": [0, 0, 0], "size": [12, 12]}, )" : "") +
                           R"({"type": "mesh", "file": "card.gltf", "transforms": [)" + card_transform + "]}]}";
  return load_scene({"card.json", json, card.read()});
}

// Where the ray through pixel (x, y) (rows from the top) meets the plane at height `height` (or,
// with `facing_z`, the plane z = 0).
std::optional<glm::vec3> pixel_on_plane(const shadow::Camera& camera, float aspect, int x, int y, int width, int height_px,
                                        float height, bool facing_z = false) {
  const glm::mat4 inverse = glm::inverse(camera.projection(aspect) * camera.view());
  const glm::vec2 ndc((x + 0.5f) / width * 2.0f - 1.0f, 1.0f - (y + 0.5f) / height_px * 2.0f);
  const glm::vec4 near = inverse * glm::vec4(ndc, -1.0f, 1.0f), far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 a = glm::vec3(near) / near.w, b = glm::vec3(far) / far.w;
  const float from = facing_z ? a.z : a.y - height, to = facing_z ? b.z : b.y - height;
  if ((from > 0) == (to > 0)) return std::nullopt;
  return a + (b - a) * (from / (from - to));
}

// The card faces the camera 4 m away, against the sky: where the mask keeps it the pixel has the
// checker square's colour (red or blue as the lit colour's strongest channel, by a margin: the
// light adds some white), where it cuts the card away the sky shows.
TEST(SurfaceTexture, APolygonShowsItsTexturesColoursAndTheSkyWhereTheMaskCutsItAway) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const Scene scene = card_scene(R"({"position": [0, 1, 4], "target": [0, 1, 0], "fov_y_deg": 40})",
                                 R"({"type": "directional", "direction": [0, -0.3, -1]})", "[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]", false);
  RenderSettings settings;
  settings.width = 320;
  settings.height = 240;
  settings.method = shadow::Method::none;
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  const Image8 color = renderer.frame().read_color();
  const glm::ivec3 sky(color.at(0, 0, 0), color.at(0, 0, 1), color.at(0, 0, 2));
  std::size_t red = 0, blue = 0, cut = 0, wrong = 0;
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      const auto p = pixel_on_plane(scene.camera, 320.0f / 240.0f, x, y, settings.width, settings.height, 0.0f, true);
      if (!p || std::abs(p->x) > 0.95f || p->y < 0.05f || p->y > 1.95f) continue;  // off the card, or at its rim
      const glm::vec2 uv((p->x + 1.0f) / 2.0f, 1.0f - p->y / 2.0f);
      if (distance_to_mask_edge(uv) < 0.02f || distance_to_checker_edge(uv) < 0.02f) continue;
      const glm::ivec3 c(color.at(x, y, 0), color.at(x, y, 1), color.at(x, y, 2));
      if (!card_keeps(uv)) {
        ++cut;
        wrong += c != sky;
      } else if (card_color(uv).r > 0.5f) {
        ++red;
        wrong += !(c.r > c.g + 60 && c.r > c.b + 60);
      } else {
        ++blue;
        wrong += !(c.b > c.r + 60 && c.b > c.g + 60);
      }
    }
  }
  std::cout << red << " red, " << blue << " blue, " << cut << " cut-away pixels checked; " << wrong << " wrong\n";
  EXPECT_GT(red, 2000u);
  EXPECT_GT(blue, 2000u);
  EXPECT_GT(cut, 2000u);
  EXPECT_LE(wrong, (red + blue + cut) / 200);
}

// The card close up (about 2.6 pixels a texel) with a nearest sampler: a pixel within a fifth of a
// texel of the edge between two checker squares shows its own square's colour, not a blend.
TEST(SurfaceTexture, ANearestTextureMagnifiedShowsEachTexelFlat) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const Scene scene = card_scene(R"({"position": [0, 1, 4], "target": [0, 1, 0], "fov_y_deg": 40})",
                                 R"({"type": "directional", "direction": [0, -0.3, -1]})", "[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]", false,
                                 9728);
  RenderSettings settings;
  settings.width = 320;
  settings.height = 240;
  settings.method = shadow::Method::none;
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  const Image8 color = renderer.frame().read_color();
  std::size_t checked = 0, blended = 0;
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      const auto p = pixel_on_plane(scene.camera, 320.0f / 240.0f, x, y, settings.width, settings.height, 0.0f, true);
      if (!p || std::abs(p->x) > 0.95f || p->y < 0.05f || p->y > 1.95f) continue;
      const glm::vec2 uv((p->x + 1.0f) / 2.0f, 1.0f - p->y / 2.0f);
      if (!card_keeps(uv) || distance_to_mask_edge(uv) < 0.02f || distance_to_checker_edge(uv) > 0.2f / card_texels) continue;
      const glm::ivec3 c(color.at(x, y, 0), color.at(x, y, 1), color.at(x, y, 2));
      ++checked;
      blended += card_color(uv).r > 0.5f ? !(c.r > c.b + 60) : !(c.b > c.r + 60);
    }
  }
  std::cout << checked << " pixels beside a checker edge, " << blended << " of them blended\n";
  EXPECT_GT(checked, 300u);
  EXPECT_LE(blended, checked / 100);
}

// The card lies flat 1 m above the ground (x and z from -1 to 1), the sun nearly overhead: the
// ground pixels whose ray toward the sun meets the card inside the disc its mask keeps, and those
// meeting it in the square's rest, away from the card's and the disc's rims.
struct CardShadow {
  std::size_t disc = 0, disc_shadowed = 0, square = 0, square_lit = 0;
};

CardShadow card_shadow(const std::string& camera, shadow::Method method) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const glm::vec3 light = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
  // Card (x, y, 0) to (x, 1, 1 - y): u = (x + 1) / 2, v = (z + 1) / 2 there.
  const Scene scene = card_scene(camera, R"({"type": "directional", "direction": [0.2, -1, 0.1]})",
                                 "[1,0,0,0, 0,0,-1,0, 0,1,0,0, 0,1,1,1]", true);
  RenderSettings settings;
  settings.width = 480;
  settings.height = 360;
  settings.shadow_size = 2048;
  settings.method = method;
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  const Image8 visibility = renderer.frame().read_visibility();
  const float aspect = 480.0f / 360.0f;
  CardShadow counts;
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      // Pixels that see the card, or might at its rim, are not the ground's.
      if (const auto on_card = pixel_on_plane(scene.camera, aspect, x, y, settings.width, settings.height, 1.0f);
          on_card && std::abs(on_card->x) < 1.05f && std::abs(on_card->z) < 1.05f) {
        continue;
      }
      const auto ground = pixel_on_plane(scene.camera, aspect, x, y, settings.width, settings.height, 0.0f);
      if (!ground) continue;
      const glm::vec3 caster = *ground - light * (1.0f / -light.y);  // toward the light, up to the card's height
      if (std::abs(caster.x) > 0.98f || std::abs(caster.z) > 0.98f) continue;  // not under the card, or at its edge
      const glm::vec2 uv((caster.x + 1.0f) / 2.0f, (caster.z + 1.0f) / 2.0f);
      if (distance_to_mask_edge(uv) < 0.03f) continue;  // within 6 cm of the disc's rim
      const bool shadowed = visibility.at(x, y) < 128;
      if (card_keeps(uv)) {
        ++counts.disc;
        counts.disc_shadowed += shadowed;
      } else {
        ++counts.square;
        counts.square_lit += !shadowed;
      }
    }
  }
  std::cout << shadow::technique(method).name << ": under the disc " << counts.disc_shadowed << "/" << counts.disc
            << " shadowed, under the rest of the card " << counts.square_lit << "/" << counts.square << " lit\n";
  return counts;
}

void expect_the_masks_shape(const CardShadow& counts) {
  EXPECT_GT(counts.disc, 1000u);
  EXPECT_GT(counts.square, 500u);
  EXPECT_GE(counts.disc_shadowed, counts.disc * 99 / 100);
  EXPECT_GE(counts.square_lit, counts.square * 99 / 100);
}

// Seen from above and aside, in every method.
class MaskedShadow : public testing::TestWithParam<shadow::Method> {};

TEST_P(MaskedShadow, TheShadowOfAMaskedCardIsTheMasksShape) {
  expect_the_masks_shape(card_shadow(R"({"position": [0, 4, 5], "target": [0, 0, 0], "fov_y_deg": 40})", GetParam()));
}

// The eye under the card, in its shadow: inside the masked triangles' prisms, whose faces all face
// away from it, the shadow volumes still find the mask's shape (and the hybrid, whose volumes
// decide near its map's edges).
TEST(MaskedShadowVolumes, AnEyeInsideTheMaskedCardsShadowSeesTheMasksShape) {
  for (const shadow::Method method : {shadow::Method::volumes, shadow::Method::hybrid}) {
    expect_the_masks_shape(card_shadow(R"({"position": [0, 0.5, 0], "target": [0, 0, -1.5], "fov_y_deg": 90})", method));
  }
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, MaskedShadow, testing::ValuesIn(test::methods_with_shadows()),
                         [](const testing::TestParamInfo<shadow::Method>& info) { return test::test_name(info.param); });

}  // namespace
}  // namespace ecoview
