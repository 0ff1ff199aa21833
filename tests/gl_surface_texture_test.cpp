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
                 const TexturedCard& card = textured_card()) {
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

// The card facing the camera 4 m away against the sky, lit, without shadows (320 × 240, about
// 2.6 pixels a texel): its colours, and the texture coordinate each pixel sees on its plane.
struct FacingCard {
  static constexpr int width = 320, height = 240;
  Image8 color;
  shadow::Camera camera;

  glm::ivec3 at(int x, int y) const { return {color.at(x, y, 0), color.at(x, y, 1), color.at(x, y, 2)}; }
  glm::ivec3 sky() const { return at(0, 0); }
  // Where the pixel sees the card away from its rim (a fortieth of its side), none elsewhere.
  std::optional<glm::vec2> uv(int x, int y) const {
    const auto p = pixel_on_plane(camera, static_cast<float>(width) / height, x, y, width, height, 0.0f, true);
    if (!p) return std::nullopt;
    const glm::vec2 uv((p->x + 1.0f) / 2.0f, 1.0f - p->y / 2.0f);
    if (glm::any(glm::lessThan(uv, glm::vec2(0.025f))) || glm::any(glm::greaterThan(uv, glm::vec2(0.975f)))) return std::nullopt;
    return uv;
  }
};

FacingCard facing_card(const TexturedCard& card) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const Scene scene = card_scene(R"({"position": [0, 1, 4], "target": [0, 1, 0], "fov_y_deg": 40})",
                                 R"({"type": "directional", "direction": [0, -0.3, -1]})", "[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]", false,
                                 card);
  RenderSettings settings;
  settings.width = FacingCard::width;
  settings.height = FacingCard::height;
  settings.method = shadow::Method::none;
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  return {renderer.frame().read_color(), scene.camera};
}

// Where the mask keeps the card the pixel has the checker square's colour (red or blue as the lit
// colour's strongest channel, by a margin: the light adds some white), where it cuts the card away
// the sky shows.
TEST(SurfaceTexture, APolygonShowsItsTexturesColoursAndTheSkyWhereTheMaskCutsItAway) {
  const FacingCard view = facing_card(textured_card());
  std::size_t red = 0, blue = 0, cut = 0, wrong = 0;
  for (int y = 0; y < FacingCard::height; ++y) {
    for (int x = 0; x < FacingCard::width; ++x) {
      const std::optional<glm::vec2> uv = view.uv(x, y);
      if (!uv || distance_to_mask_edge(*uv) < 0.02f || distance_to_checker_edge(*uv) < 0.02f) continue;
      const glm::ivec3 c = view.at(x, y);
      if (!card_keeps(*uv)) {
        ++cut;
        wrong += c != view.sky();
      } else if (card_color(*uv).r > 0.5f) {
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

// With vertex colours whose alpha fades from 1 on the card's left edge to 0 on its right, the
// polygon keeps the disc's left half (u < 0.5), where the texture's alpha × the interpolated
// vertex alpha reaches the cutoff, and shows the sky in its right half.
TEST(SurfaceTexture, TheVertexColoursAlphaCutsThePolygonAsTheMask) {
  const FacingCard view = facing_card(textured_card_fading_to_the_right());
  std::size_t left = 0, right = 0, wrong = 0;
  for (int y = 0; y < FacingCard::height; ++y) {
    for (int x = 0; x < FacingCard::width; ++x) {
      const std::optional<glm::vec2> uv = view.uv(x, y);
      if (!uv || !card_keeps(*uv) || distance_to_mask_edge(*uv) < 0.02f || std::abs(uv->x - 0.5f) < 0.02f) continue;
      const bool shows_sky = view.at(x, y) == view.sky();
      if (uv->x < 0.5f) {
        ++left;
        wrong += shows_sky;
      } else {
        ++right;
        wrong += !shows_sky;
      }
    }
  }
  std::cout << left << " pixels left of the cut, " << right << " right of it; " << wrong << " wrong\n";
  EXPECT_GT(left, 2000u);
  EXPECT_GT(right, 2000u);
  EXPECT_LE(wrong, (left + right) / 200);
}

// With a nearest sampler, magnified, a pixel within a fifth of a texel of the edge between two
// checker squares shows its own square's colour, not a blend.
TEST(SurfaceTexture, ANearestTextureMagnifiedShowsEachTexelFlat) {
  const FacingCard view = facing_card(textured_card("MASK", 9728));
  std::size_t checked = 0, blended = 0;
  for (int y = 0; y < FacingCard::height; ++y) {
    for (int x = 0; x < FacingCard::width; ++x) {
      const std::optional<glm::vec2> uv = view.uv(x, y);
      if (!uv || !card_keeps(*uv) || distance_to_mask_edge(*uv) < 0.02f || distance_to_checker_edge(*uv) > 0.2f / card_texels) continue;
      const glm::ivec3 c = view.at(x, y);
      ++checked;
      blended += card_color(*uv).r > 0.5f ? !(c.r > c.b + 60) : !(c.b > c.r + 60);
    }
  }
  std::cout << checked << " pixels beside a checker edge, " << blended << " of them blended\n";
  EXPECT_GT(checked, 300u);
  EXPECT_LE(blended, checked / 100);
}

// A plain plant near the camera, drawn as polygons, is drawn the same whether or not the scene
// holds a textured mesh (here out of view, behind the camera): its polygons then take the
// textured programs, with no texture and no mask of their own.
TEST(SurfaceTexture, APlainPlantBesideATexturedMeshIsDrawnWhole) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  const TexturedCard card = textured_card();
  const std::string plant = R"({"camera": {"position": [0, 3, 0], "target": [0, 3, -20], "fov_y_deg": 50},
      "lights": [{"type": "directional", "direction": [0.4, -0.8, -0.3]}],
      "objects": [{"type": "plant", "species": "beech", "positions": [[0, 0, -9]]})";
  const std::string behind = R"(, {"type": "mesh", "file": "card.gltf", "transforms": [[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,30,1]]})";
  RenderSettings settings;
  settings.width = 320;
  settings.height = 240;
  settings.method = shadow::Method::none;
  Image8 color[2];
  std::size_t triangles[2];
  int i = 0;
  for (const std::string& json : {plant + "]}", plant + behind + "]}"}) {
    const Scene scene = load_scene({"plant.json", json, card.read()});
    Renderer renderer(scene, settings);
    renderer.render(scene.camera, scene.lights[0]);
    color[i] = renderer.frame().read_color();
    triangles[i++] = renderer.stats().triangles;
  }
  ASSERT_GT(triangles[0], 1000u) << "the near beech should be polygons";
  ASSERT_GT(triangles[1], 1000u);
  std::size_t differ = 0;
  for (std::size_t k = 0; k < color[0].samples.size(); ++k) differ += color[0].samples[k] != color[1].samples[k];
  EXPECT_EQ(differ, 0u);
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
