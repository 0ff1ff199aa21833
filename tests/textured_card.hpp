#pragma once
#include "pointgen/mesh_file.hpp"

#include <glm/glm.hpp>

#include <map>
#include <string>

namespace ecoview {

// A leaf card as a user's glTF file, written by the test: a 2 × 2 m quad in the x-y plane (x from
// -1 to 1, y from 0 to 2, facing +z), textured by an image whose colour is a checkerboard of
// red and blue squares and whose alpha keeps only a disc (alphaMode MASK). Texture coordinates:
// u = (x + 1) / 2, v = 1 - y / 2 (glTF's v runs down the image).
struct TexturedCard {
  std::map<std::string, std::string> files;  // "card.gltf", "card.bin", "leaf.png"
  pointgen::ReadFile read() const;
};

// `alpha_mode` "MASK", "BLEND" or "OPAQUE"; `mag_filter` the sampler's (GL_LINEAR or GL_NEAREST).
TexturedCard textured_card(const std::string& alpha_mode = "MASK", int mag_filter = 9729);
// The card with vertex colours (COLOR_0) whose alpha is 1 on its left edge (x = -1) and 0 on its
// right (x = 1): with the mask's cutoff 0.5 it keeps the disc's left half.
TexturedCard textured_card_fading_to_the_right();
// The same card in one .glb file ("card.glb") whose buffer holds the image as JPEG (no alpha:
// opaque).
TexturedCard textured_card_glb_with_jpeg();

constexpr int card_texels = 64;           // the image's side
constexpr int card_checker_texels = 8;    // a checker square's side
constexpr float card_disc_radius = 0.35f; // in texture coordinates, around (0.5, 0.5)

// Whether the mask keeps the card at `uv`, and how far `uv` lies from the mask's edge and from
// the nearest checker square's edge (texture coordinates).
bool card_keeps(glm::vec2 uv);
float distance_to_mask_edge(glm::vec2 uv);
float distance_to_checker_edge(glm::vec2 uv);
// The checkerboard's colour at `uv`, sRGB: red (1, 0, 0) or blue (0, 0, 1).
glm::vec3 card_color(glm::vec2 uv);

}  // namespace ecoview
