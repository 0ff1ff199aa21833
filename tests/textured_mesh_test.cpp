// Textured and alpha-masked glTF meshes: what the loader reads, and the surface samples taken
// from them, against the texture and mask the test wrote.
#include "textured_card.hpp"

#include "pointgen/file_error.hpp"
#include "pointgen/sampling/surface_samples.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ecoview {
namespace {

// The card's texture coordinate at a point of its plane (textured_card.hpp).
glm::vec2 card_uv(const glm::vec3& p) { return {(p.x + 1.0f) / 2.0f, 1.0f - p.y / 2.0f}; }

constexpr float texel = 1.0f / card_texels;

std::string load_failure(const TexturedCard& card) {
  try {
    pointgen::load_mesh_file("card.gltf", card.read());
  } catch (const pointgen::FileError& e) {
    return e.what();
  }
  return "";
}

TEST(TexturedGltf, ACardLoadsWithItsImageTextureCoordinatesAndMask) {
  const pointgen::TriangleMesh mesh = pointgen::load_mesh_file("card.gltf", textured_card().read());
  ASSERT_EQ(mesh.materials.size(), 2u) << "the plain material and the card's";
  const pointgen::SurfaceMaterial& card = mesh.materials[1];
  ASSERT_TRUE(card.texture);
  EXPECT_EQ(card.texture->width, card_texels);
  EXPECT_EQ(card.texture->height, card_texels);
  EXPECT_FLOAT_EQ(card.alpha_cutoff, 0.5f) << "MASK with glTF's default cutoff";
  EXPECT_EQ(card.texture->wrap_s, pointgen::SurfaceTexture::Wrap::clamp);
  ASSERT_EQ(mesh.texcoords.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(mesh.vertex_materials[i], 1u);
    EXPECT_NEAR(glm::distance(mesh.texcoords[i], card_uv(mesh.positions[i])), 0.0f, 1e-6f);
  }
  EXPECT_EQ(mesh.texture_bytes(), 4u * card_texels * card_texels);
  // The image's texel at the card's centre: inside the disc, of the checker square there.
  const glm::vec4 centre = card.texture->sample({0.5f + 0.5f * texel, 0.5f + 0.5f * texel});
  EXPECT_NEAR(centre.a, 1.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(glm::vec3(centre), card_color({0.5f + 0.5f * texel, 0.5f + 0.5f * texel})), 0.0f, 1e-6f);
}

// The sampler's magnification filter: 0.3 texels from the edge between two checker squares, a
// nearest image gives the square's own colour, a linear one a blend of the two.
TEST(TexturedGltf, ANearestSamplerShowsTheTexelTheCoordinateFallsIn) {
  const glm::vec2 uv(0.5f - 0.3f * texel, 0.5f + 0.5f * texel);  // left of the edge at u = 0.5
  const glm::vec3 square = card_color(uv), beside = card_color(uv + glm::vec2(0.6f * texel, 0.0f));
  ASSERT_NE(square, beside);
  const pointgen::TriangleMesh nearest = pointgen::load_mesh_file("card.gltf", textured_card("MASK", 9728).read());
  ASSERT_TRUE(nearest.materials[1].texture);
  EXPECT_EQ(nearest.materials[1].texture->magnify, pointgen::SurfaceTexture::Filter::nearest);
  EXPECT_NEAR(glm::distance(glm::vec3(nearest.materials[1].texture->sample(uv)), square), 0.0f, 1e-6f);
  const pointgen::TriangleMesh linear = pointgen::load_mesh_file("card.gltf", textured_card("MASK", 9729).read());
  const glm::vec3 blend = glm::vec3(linear.materials[1].texture->sample(uv));
  EXPECT_NEAR(glm::distance(blend, 0.8f * square + 0.2f * beside), 0.0f, 1e-5f);
}

// The image embedded in a .glb's buffer, as JPEG: decoded, the checkerboard's colours within
// JPEG's error away from the squares' edges.
TEST(TexturedGltf, AJpegImageEmbeddedInABinaryFileIsDecoded) {
  const pointgen::TriangleMesh mesh = pointgen::load_mesh_file("card.glb", textured_card_glb_with_jpeg().read());
  ASSERT_EQ(mesh.materials.size(), 2u);
  ASSERT_TRUE(mesh.materials[1].texture);
  EXPECT_FALSE(mesh.materials[1].masked());
  for (int i = 0; i < 64; ++i) {
    const glm::vec2 uv = (glm::vec2(i % 8, i / 8) + 0.5f) / 8.0f;  // the squares' centres
    const glm::vec3 c = glm::vec3(mesh.materials[1].texture->sample(uv));
    EXPECT_NEAR(glm::distance(c, card_color(uv)), 0.0f, 0.1f) << uv.x << ", " << uv.y;
  }
}

TEST(TexturedGltf, AnImageThatCannotBeDecodedIsRefusedByItsIndexAndFile) {
  TexturedCard card = textured_card();
  card.files["leaf.png"] = "not an image at all";
  const std::string message = load_failure(card);
  EXPECT_NE(message.find("card.gltf: images[0].uri: leaf.png: cannot be decoded"), std::string::npos) << message;
  // A PNG whose header claims 16,385 × 1,000 texels: wider than a texture may be, refused from the
  // header before anything is decoded (stb_image itself refuses images over 1 GiB).
  std::string& png = card.files["leaf.png"] = textured_card().files.at("leaf.png");
  png.replace(16, 8, std::string("\x00\x00\x40\x01\x00\x00\x03\xe8", 8));
  const std::string huge = load_failure(card);
  EXPECT_NE(huge.find("images[0].uri: leaf.png: 16385 x 1000 texels, more than 16384 a side"), std::string::npos) << huge;
}

TEST(TexturedGltf, AMissingImageFileIsNamedWithItsField) {
  TexturedCard card = textured_card();
  card.files.erase("leaf.png");
  EXPECT_EQ(load_failure(card), "card.gltf: images[0].uri: leaf.png: no such file");
}

TEST(TexturedGltf, WhatIsNotUsedIsSaidInOneLine) {
  TexturedCard card = textured_card("BLEND");
  card.files["card.gltf"].insert(1, R"("extensionsUsed": ["KHR_texture_transform"], )");
  std::string& gltf = card.files["card.gltf"];
  gltf.insert(gltf.find(R"("wrapS")"), R"("minFilter": 9728, )");  // NEAREST, no mipmaps
  std::vector<std::string> notes;
  const pointgen::TriangleMesh mesh =
      pointgen::load_mesh_file("card.gltf", card.read(), [&](const std::string& line) { notes.push_back(line); });
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "card.gltf: ignored: alpha blending (drawn as MASK at 0.5), minification filters (drawn trilinear), KHR_texture_transform");
  EXPECT_FLOAT_EQ(mesh.materials.at(1).alpha_cutoff, 0.5f);
  notes.clear();
  pointgen::load_mesh_file("card.gltf", textured_card().read(), [&](const std::string& line) { notes.push_back(line); });
  EXPECT_TRUE(notes.empty()) << "a file with nothing ignored says nothing";
}

// The points on a masked card lie in the disc its mask keeps (up to a texel from the edge, where
// the mask is filtered between texels), spread evenly over it, and the card's area is the disc's.
TEST(TexturedSurfaceSamples, LieOnlyWhereTheMaskKeepsTheCardAndSpreadOverTheKeptArea) {
  const pointgen::TriangleMesh mesh = pointgen::load_mesh_file("card.gltf", textured_card().read());
  const float disc = 3.14159265f * card_disc_radius * card_disc_radius * 4.0f;  // the card is 2 × 2 m
  EXPECT_NEAR(pointgen::surface_area(mesh), disc, 0.02f * disc);
  const std::vector<pointgen::SurfaceSample> samples = pointgen::sample_surface(mesh, 20000, 5);
  ASSERT_EQ(samples.size(), 20000u);
  std::size_t inner = 0;
  for (const pointgen::SurfaceSample& s : samples) {
    const glm::vec2 uv = card_uv(s.position);
    ASSERT_TRUE(card_keeps(uv) || distance_to_mask_edge(uv) < texel) << uv.x << ", " << uv.y;
    inner += glm::distance(uv, glm::vec2(0.5f)) < card_disc_radius / std::sqrt(2.0f);
  }
  EXPECT_NEAR(static_cast<double>(inner) / samples.size(), 0.5, 0.02) << "half the disc's area, half its points";
}

// The vertex colours' alpha, interpolated, scales the texture's before the cutoff (glTF): 1 × (1 -
// u) ≥ 0.5 keeps the disc's left half, u ≤ 0.5. Interpolating the cutoff over the alpha instead
// would keep only u ≤ 1/3.
TEST(TexturedSurfaceSamples, TheVertexColoursAlphaEntersTheMask) {
  const pointgen::TriangleMesh mesh = pointgen::load_mesh_file("card.gltf", textured_card_fading_to_the_right().read());
  const float half_disc = 3.14159265f * card_disc_radius * card_disc_radius * 2.0f;
  EXPECT_NEAR(pointgen::surface_area(mesh), half_disc, 0.03f * half_disc);
  std::size_t near_the_cut = 0;
  for (const pointgen::SurfaceSample& s : pointgen::sample_surface(mesh, 10000, 7)) {
    const glm::vec2 uv = card_uv(s.position);
    ASSERT_TRUE(card_keeps(uv) || distance_to_mask_edge(uv) < texel) << uv.x << ", " << uv.y;
    ASSERT_LE(uv.x, 0.5f + 1e-4f) << "right of the cut";
    near_the_cut += uv.x > 0.45f;
  }
  EXPECT_GT(near_the_cut, 300u) << "up to the cut at u = 0.5";
}

TEST(TexturedSurfaceSamples, TakeTheirColourFromTheTexture) {
  const pointgen::TriangleMesh mesh = pointgen::load_mesh_file("card.gltf", textured_card("OPAQUE").read());
  EXPECT_NEAR(pointgen::surface_area(mesh), 4.0f, 1e-4f) << "no mask: the whole card";
  std::size_t checked = 0, outside_disc = 0;
  for (const pointgen::SurfaceSample& s : pointgen::sample_surface(mesh, 5000, 6)) {
    const glm::vec2 uv = card_uv(s.position);
    outside_disc += !card_keeps(uv);
    if (distance_to_checker_edge(uv) < texel) continue;  // filtered between two squares' texels
    ++checked;
    ASSERT_NEAR(glm::distance(s.color, card_color(uv)), 0.0f, 1e-5f) << uv.x << ", " << uv.y;  // red and blue are linear too
  }
  EXPECT_GT(checked, 2500u);  // more than half are a texel from every square's edge
  EXPECT_GT(outside_disc, 2000u) << "an opaque card is sampled all over";
}

}  // namespace
}  // namespace ecoview
