#include "textured_card.hpp"

#include <stb/stb_image_write.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace ecoview {
namespace {

std::string jpeg_of(const std::vector<std::uint8_t>& rgba, int side) {
  std::string jpeg;
  stbi_write_jpg_to_func([](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<const char*>(data), static_cast<std::size_t>(size)); },
                         &jpeg, side, side, 4, rgba.data(), 95);
  return jpeg;
}

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

namespace {

std::vector<std::uint8_t> card_texels_rgba() {
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < card_texels; ++y) {
    for (int x = 0; x < card_texels; ++x) {
      const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / static_cast<float>(card_texels);
      const glm::vec3 c = card_color(uv);
      rgba.insert(rgba.end(), {static_cast<std::uint8_t>(255 * c.r), static_cast<std::uint8_t>(255 * c.g),
                               static_cast<std::uint8_t>(255 * c.b), static_cast<std::uint8_t>(card_keeps(uv) ? 255 : 0)});
    }
  }
  return rgba;
}

std::string card_geometry() {
  std::string bin;
  append(bin, std::vector<float>{-1, 0, 0, 1, 0, 0, 1, 2, 0, -1, 2, 0});  // positions
  append(bin, std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});   // normals
  append(bin, std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0});               // texture coordinates
  append(bin, std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
  return bin;
}

// The card's glTF JSON: `buffer` and `image` as JSON objects, bufferView 4 free for an image.
// With `colours`, vertex colours (COLOR_0, RGBA floats) in bufferView 4 after the geometry.
std::string card_json(const std::string& buffer, const std::string& image, const std::string& extra_view,
                      const std::string& alpha_mode, int mag_filter = 9729, bool colours = false) {
  const std::string colour_view = colours ? R"(, {"buffer": 0, "byteOffset": 140, "byteLength": 64})" : "";
  const std::string colour_accessor = colours ? R"(, {"bufferView": 4, "componentType": 5126, "count": 4, "type": "VEC4"})" : "";
  const std::string colour_attribute = colours ? R"(, "COLOR_0": 4)" : "";
  return R"({"asset": {"version": "2.0"}, "buffers": [)" + buffer + R"(],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                    {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 12})" + extra_view + colour_view + R"(],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, 0], "max": [1, 2, 0]},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                  {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"})" + colour_accessor + R"(],
    "images": [)" + image + R"(], "samplers": [{"wrapS": 33071, "wrapT": 33071, "magFilter": )" + std::to_string(mag_filter) + R"(}],
    "textures": [{"source": 0, "sampler": 0}],
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}, "alphaMode": ")" + alpha_mode + R"(", "doubleSided": true}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2)" + colour_attribute + R"(}, "indices": 3, "material": 0}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
}

std::string little_endian(std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); }

}  // namespace

TexturedCard textured_card(const std::string& alpha_mode, int mag_filter) {
  const std::string gltf = card_json(R"({"uri": "card.bin", "byteLength": 140})", R"({"uri": "leaf.png"})", "", alpha_mode, mag_filter);
  return {{{"card.gltf", gltf}, {"card.bin", card_geometry()}, {"leaf.png", png_of(card_texels_rgba(), card_texels)}}};
}

TexturedCard textured_card_fading_to_the_right() {
  std::string bin = card_geometry();
  append(bin, std::vector<float>{1, 1, 1, 1, 1, 1, 1, 0, 1, 1, 1, 0, 1, 1, 1, 1});  // alpha 1 at x = -1, 0 at x = 1
  const std::string gltf = card_json(R"({"uri": "card.bin", "byteLength": 204})", R"({"uri": "leaf.png"})", "", "MASK", 9729, true);
  return {{{"card.gltf", gltf}, {"card.bin", bin}, {"leaf.png", png_of(card_texels_rgba(), card_texels)}}};
}

TexturedCard textured_card_glb_with_jpeg() {
  std::string bin = card_geometry();
  const std::string jpeg = jpeg_of(card_texels_rgba(), card_texels);
  const std::string view = R"(, {"buffer": 0, "byteOffset": 140, "byteLength": )" + std::to_string(jpeg.size()) + "}";
  bin += jpeg;
  bin.append(-bin.size() % 4, '\0');
  std::string json = card_json(R"({"byteLength": )" + std::to_string(bin.size()) + "}",
                               R"({"bufferView": 4, "mimeType": "image/jpeg"})", view, "OPAQUE");
  json.append(-json.size() % 4, ' ');
  const std::string glb = "glTF" + little_endian(2) + little_endian(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size())) +
                          little_endian(static_cast<std::uint32_t>(json.size())) + "JSON" + json +
                          little_endian(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
  return {{{"card.glb", glb}}};
}

}  // namespace ecoview
