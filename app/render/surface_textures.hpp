#pragma once
#include "app/gl/gl_objects.hpp"
#include "pointgen/triangle_mesh.hpp"

#include <map>
#include <vector>

namespace ecoview {

// The meshes' base-colour textures for their polygons (shaders/surface_texture.glsl): one sRGB
// texture array, mipmapped, a layer a texture, every image resized to the largest one's size (at
// most 2,048 a side, less where the array would pass 512 MiB). Each vertex of a mesh with materials carries its texture coordinate and its
// material as a code (vertex_surfaces); the points take their colours from the images at load.
class SurfaceTextures {
 public:
  explicit SurfaceTextures(const std::vector<pointgen::TriangleMesh>& meshes);
  // Whether any mesh has a texture or an alpha mask: the polygon programs that draw the scene need
  // the SURFACE_TEXTURES variant.
  bool any() const { return any_; }
  // Per vertex of `mesh` (one with materials): texture coordinate, then the code of its material's
  // texture layer and wrap modes, then its mask's keep scale (SurfaceMaterial::keep_scale).
  std::vector<glm::vec4> vertex_surfaces(const pointgen::TriangleMesh& mesh) const;
  void bind() const;

 private:
  bool any_ = false;
  std::map<const pointgen::SurfaceTexture*, int> layers_;
  gl::Texture array_{GL_TEXTURE_2D_ARRAY};
};

}  // namespace ecoview
