#include "textured_card.hpp"

#include <stb/stb_image_write.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace ecoview {
namespace {

std::string png_of(const std::vector<std::uint8_t>& rgba, int side) {
  std::string png;
  stbi_write_png_to_func([](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<const char*>(data), static_cast<std::size_t>(size)); },
                         &png, side, side, 4, rgba.data(), 4 * side);
  return png;
}

template <class T>
void append(std::string& bytes, const std::vector<T>& values) {
  bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

}  // namespace

pointgen::ReadFile TexturedCard::read() const {
  return [files = files](const std::string& path) -> std::optional<std::string> {
    const auto it = files.find(path);
    if (it == files.end()) return std::nullopt;
    return it->second;
  };
}

bool card_keeps(glm::vec2 uv) { return glm::distance(uv, glm::vec2(0.5f)) < card_disc_radius; }

float distance_to_mask_edge(glm::vec2 uv) { return std::abs(glm::distance(uv, glm::vec2(0.5f)) - card_disc_radius); }

float distance_to_checker_edge(glm::vec2 uv) {
  const float square = static_cast<float>(card_checker_texels) / card_texels;
  const glm::vec2 within = glm::mod(uv, square);
  return std::min(std::min(within.x, square - within.x), std::min(within.y, square - within.y));
}

glm::vec3 card_color(glm::vec2 uv) {
  const float square = static_cast<float>(card_checker_texels) / card_texels;
  const int i = static_cast<int>(std::floor(uv.x / square)) + static_cast<int>(std::floor(uv.y / square));
  return i % 2 == 0 ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
}

TexturedCard textured_card(const std::string& alpha_mode) {
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < card_texels; ++y) {
    for (int x = 0; x < card_texels; ++x) {
      const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / static_cast<float>(card_texels);
      const glm::vec3 c = card_color(uv);
      rgba.insert(rgba.end(), {static_cast<std::uint8_t>(255 * c.r), static_cast<std::uint8_t>(255 * c.g),
                               static_cast<std::uint8_t>(255 * c.b), static_cast<std::uint8_t>(card_keeps(uv) ? 255 : 0)});
    }
  }
  std::string bin;
  append(bin, std::vector<float>{-1, 0, 0, 1, 0, 0, 1, 2, 0, -1, 2, 0});  // positions
  append(bin, std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});   // normals
  append(bin, std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0});               // texture coordinates
  append(bin, std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
  const std::string gltf = R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "card.bin", "byteLength": 140}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                    {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, 0], "max": [1, 2, 0]},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                  {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    "images": [{"uri": "leaf.png"}], "samplers": [{"wrapS": 33071, "wrapT": 33071}],
    "textures": [{"source": 0, "sampler": 0}],
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}, "alphaMode": ")" + alpha_mode + R"(", "doubleSided": true}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
  return {{{"card.gltf", gltf}, {"card.bin", bin}, {"leaf.png", png_of(rgba, card_texels)}}};
}

}  // namespace ecoview
