#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace pointgen {

// A material's base-colour image (glTF baseColorTexture): 8-bit RGBA, colour in sRGB, alpha
// linear, row 0 at texture coordinate v = 0, looked up as GL does with its sampler's wrap modes and
// magnification filter. Minified, it is always filtered through its mipmaps.
struct SurfaceTexture {
  enum class Wrap { repeat, clamp, mirror };
  enum class Filter { linear, nearest };
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width × height × 4
  Wrap wrap_s = Wrap::repeat, wrap_t = Wrap::repeat;
  Filter magnify = Filter::linear;

  // The full-size image at `uv` as it is magnified: bilinear between the four texels around it
  // (GL_LINEAR), or the texel it falls in (GL_NEAREST). Linear RGB and alpha.
  glm::vec4 sample(glm::vec2 uv) const;
  std::size_t bytes() const { return rgba.size(); }
};

// How a surface is coloured and cut beyond its vertex colours: a texture multiplied in, and an
// alpha mask (glTF alphaMode MASK): the surface exists only where texture alpha × `alpha` × the
// vertex colour's alpha is at least `alpha_cutoff`.
struct SurfaceMaterial {
  std::shared_ptr<const SurfaceTexture> texture;  // none: vertex colours alone
  float alpha = 1.0f;                             // the base colour factor's alpha
  float alpha_cutoff = 0.0f;                      // 0: opaque, no mask

  bool masked() const { return alpha_cutoff > 0.0f; }
  // The texture at `uv` (linear RGB to multiply the vertex colour by, and alpha; white without a
  // texture).
  glm::vec4 texel(glm::vec2 uv) const;
  // What texture alpha is multiplied by for the mask to keep the surface where the product reaches
  // 1, at a vertex of alpha `vertex_alpha`: alpha × vertex_alpha / alpha_cutoff, linear in the
  // vertex's alpha so that it interpolates across a triangle as that does; -1 without a mask.
  float keep_scale(float vertex_alpha) const;

};

}  // namespace pointgen
