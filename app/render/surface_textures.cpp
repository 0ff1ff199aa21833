#include "app/render/surface_textures.hpp"

#include "app/errors.hpp"
#include "app/render/buffer_texture_units.hpp"

#include <stb/stb_image_resize.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ecoview {
namespace {

constexpr int max_layer_side = 2048;
// Smaller images are enlarged to the layers' size: the size halves while the array, mipmaps
// included, would take more than this.
constexpr double max_array_bytes = 512.0 * 1024 * 1024;
constexpr int max_layers = 255;  // a code's low byte holds the layer + 1
constexpr int nearest_code = 4096;  // a code's bit for nearest magnification (shaders/surface_texture.glsl)

int wrap_code(pointgen::SurfaceTexture::Wrap wrap) {
  switch (wrap) {
    case pointgen::SurfaceTexture::Wrap::clamp: return 1;
    case pointgen::SurfaceTexture::Wrap::mirror: return 2;
    case pointgen::SurfaceTexture::Wrap::repeat: break;
  }
  return 0;
}

// A nearest-magnified image enlarged or shrunk to `side` texels a side by repeating its texels, so
// that the layer keeps their flat squares.
void resize_nearest(const pointgen::SurfaceTexture& texture, int side, std::vector<std::uint8_t>& out) {
  for (int y = 0; y < side; ++y) {
    const std::size_t from_y = static_cast<std::size_t>(y) * static_cast<std::size_t>(texture.height) / static_cast<std::size_t>(side);
    for (int x = 0; x < side; ++x) {
      const std::size_t from_x = static_cast<std::size_t>(x) * static_cast<std::size_t>(texture.width) / static_cast<std::size_t>(side);
      std::memcpy(&out[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x))],
                  &texture.rgba[4 * (from_y * static_cast<std::size_t>(texture.width) + from_x)], 4);
    }
  }
}

}  // namespace

SurfaceTextures::SurfaceTextures(const std::vector<pointgen::TriangleMesh>& meshes) {
  int side = 1;
  for (const pointgen::TriangleMesh& mesh : meshes) {
    any_ = any_ || !mesh.materials.empty();
    for (const pointgen::SurfaceMaterial& material : mesh.materials) {
      if (!material.texture || layers_.count(material.texture.get())) continue;
      const int layer = static_cast<int>(layers_.size());
      layers_[material.texture.get()] = layer;
      side = std::max({side, material.texture->width, material.texture->height});
    }
  }
  if (layers_.empty()) return;
  if (layers_.size() > static_cast<std::size_t>(max_layers)) {
    throw RuntimeFailure("the scene's meshes have " + std::to_string(layers_.size()) + " textures; at most " +
                         std::to_string(max_layers) + " are supported");
  }
  side = std::min(side, max_layer_side);
  while (side > 64 && static_cast<double>(layers_.size()) * side * side * 4.0 * 4.0 / 3.0 > max_array_bytes) side /= 2;
  const auto levels = static_cast<GLsizei>(std::floor(std::log2(side))) + 1;
  glTextureStorage3D(array_.name(), levels, GL_SRGB8_ALPHA8, side, side, static_cast<GLsizei>(layers_.size()));
  std::vector<std::uint8_t> resized(4 * static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
  for (const auto& [texture, layer] : layers_) {
    const std::uint8_t* pixels = texture->rgba.data();
    if (texture->width != side || texture->height != side) {
      if (texture->magnify == pointgen::SurfaceTexture::Filter::nearest) {
        resize_nearest(*texture, side, resized);
      } else {
        stbir_resize_uint8_srgb(texture->rgba.data(), texture->width, texture->height, 0, resized.data(), side, side, 0, 4, 3, 0);
      }
      pixels = resized.data();
    }
    glTextureSubImage3D(array_.name(), 0, 0, 0, layer, side, side, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  }
  glGenerateTextureMipmap(array_.name());
  glTextureParameteri(array_.name(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(array_.name(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(array_.name(), GL_TEXTURE_WRAP_S, GL_REPEAT);  // clamp and mirror are the shader's
  glTextureParameteri(array_.name(), GL_TEXTURE_WRAP_T, GL_REPEAT);
}

std::vector<glm::vec4> SurfaceTextures::vertex_surfaces(const pointgen::TriangleMesh& mesh) const {
  std::vector<float> codes;
  for (const pointgen::SurfaceMaterial& material : mesh.materials) {
    int code = 0;
    if (material.texture) {
      const pointgen::SurfaceTexture& texture = *material.texture;
      code = layers_.at(&texture) + 1 + 256 * (3 * wrap_code(texture.wrap_s) + wrap_code(texture.wrap_t)) +
             (texture.magnify == pointgen::SurfaceTexture::Filter::nearest ? nearest_code : 0);
    }
    codes.push_back(static_cast<float>(code));
  }
  std::vector<glm::vec4> surfaces;
  surfaces.reserve(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const std::uint32_t m = mesh.vertex_materials[v];
    surfaces.emplace_back(mesh.texcoords[v], codes[m], mesh.materials[m].keep_scale(mesh.alphas[v]));
  }
  return surfaces;
}

void SurfaceTextures::bind() const {
  if (!layers_.empty()) glBindTextureUnit(surface_texture_unit, array_.name());
}

}  // namespace ecoview
