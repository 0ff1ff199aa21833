#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/scene/scene.hpp"

#include <vector>

namespace ecoview {

// The scene's meshes and instance tables in GL buffers: each mesh once, drawn with one instanced
// call per group. Vertex attributes: 0 position, 1 normal, 2 colour; per instance: 3–6 model
// matrix, 7–9 normal matrix, 10 colour.
class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);
  // `mode` GL_PATCHES (of 3 vertices) for programs that tessellate.
  void draw(GLenum mode = GL_TRIANGLES) const;
  // Replaces the instances of a group with `table`, which has at most as many as the scene's
  // group: posed moving objects, or the subset a pass draws as polygons.
  void update(std::size_t group, const pointgen::InstanceTable& table);

 private:
  struct Mesh {
    gl::Buffer vertices;
    gl::Buffer indices;
    GLsizei index_count = 0;
  };
  struct Group {
    gl::VertexArray vertex_array;
    gl::Buffer instances;
    GLsizei index_count = 0;
    GLsizei instance_count = 0;  // drawn
    std::size_t capacity = 0;
  };
  std::vector<Mesh> meshes_;
  std::vector<Group> groups_;
};

}  // namespace ecoview
