#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/scene/scene.hpp"
#include "pointgen/sampling/view_sampler.hpp"

#include <vector>

namespace ecoview {

// The surface samples of every point mesh in GL buffers (positions, normals with the area of the
// sample's list as w, colours as vec4 arrays, one mesh after another), and what the view sampler
// needs to know of each mesh. A mesh's list is its whole list, as long as the most points an
// instance takes before polygons are cheaper, then the same samples again in its parts' lists.
class PointSamples {
 public:
  // Without `points` (every plant drawn as polygons) no lists are made: the meshes' bounds, area
  // and triangles are all that culling needs.
  PointSamples(const Scene& scene, float points_per_triangle, bool points);

  const std::vector<pointgen::SampledMesh>& meshes() const { return meshes_; }
  std::uint32_t first_sample(std::size_t mesh) const { return first_[mesh]; }
  // Binds the lists as RGBA32F buffer textures to their texture units (buffer_texture_units.hpp).
  void bind() const;

 private:
  std::vector<pointgen::SampledMesh> meshes_;
  std::vector<std::uint32_t> first_;
  gl::Buffer positions_, normals_, colors_;
  gl::Texture position_texels_{GL_TEXTURE_BUFFER}, normal_texels_{GL_TEXTURE_BUFFER}, color_texels_{GL_TEXTURE_BUFFER};
};

}  // namespace ecoview
