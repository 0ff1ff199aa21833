#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/surface_textures.hpp"
#include "app/scene/scene.hpp"
#include "shadow/box.hpp"

#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace ecoview {


// The scene's meshes and instance tables in GL buffers: each mesh once, drawn with one instanced
// call per group, or per polygon part of a point mesh (pointgen::split_triangles) when the sampler
// chose parts. Vertex attributes: 0 position, 1 normal, 2 colour, 11 texture coordinate and
// material (meshes with materials: SurfaceTextures); per instance: 3–6 model matrix, 7–9 normal
// matrix, 10 colour.
class GpuScene {
 public:
  // Plants drawn as polygons (a GpuSampler's): the plants resident on the GPU as a buffer texture
  // (shaders/plant_instances.glsl), a list of plant indices, and indirect draws over it
  // (DrawElementsIndirectCommand, base instance: a place in the list), at most command_count of
  // them: as many as draw_counts holds at count_slot, in uints (DrawnCommands::keep_drawn).
  struct PlantDraws {
    GLuint plants = 0, plant_indices = 0, commands = 0;
    std::size_t first_command = 0, command_count = 0;
    GLuint draw_counts = 0;
    std::size_t count_slot = 0;
  };
  static constexpr std::size_t command_bytes = 5 * sizeof(GLuint);  // DrawElementsIndirectCommand

  explicit GpuScene(const Scene& scene);
  // Whether programs that draw the scene need their SURFACE_TEXTURES variant (textures, masks).
  bool has_surface_textures() const { return textures_.any(); }
  // `mode` GL_PATCHES (of 3 vertices) for programs that tessellate. With `view` (world to clip), a
  // large mesh drawn once (the terrain) is drawn by its chunks whose boxes reach the view alone.
  void draw(GLenum mode = GL_TRIANGLES, const std::optional<glm::mat4>& view = std::nullopt) const;
  // The triangles of the meshes other than point meshes that draw(mode, view) draws.
  std::size_t fixed_triangles(const std::optional<glm::mat4>& view) const;
  // Finds each triangle's neighbours across its edges (pointgen::adjacency_indices) for
  // draw_with_adjacency and draw_chosen_with_adjacency; `scene` is the one this was made from.
  // Once, before the first draw.
  void add_adjacency(const Scene& scene);
  // Every instance whole, each triangle with its neighbours (GL_TRIANGLES_ADJACENCY), for shadow
  // volumes and silhouette maps; `view` as for draw.
  void draw_with_adjacency(const std::optional<glm::mat4>& view = std::nullopt) const;
  // Replaces a mesh other than a point mesh with `with` (a landscape's ground, made for the eye),
  // drawn by `chunks`: ranges of its index list, each culled by its box.
  void replace_mesh(std::size_t mesh, const pointgen::TriangleMesh& with, const std::vector<pointgen::PolygonPart>& chunks);
  // Replaces the instances of a group with `table`, which has at most as many as the scene's
  // group: posed moving objects, or the subset a pass draws as polygons. `parts`, for a point
  // mesh's group, has for each instance the polygon parts to draw, a bit each; none: all.
  void update(std::size_t group, const pointgen::InstanceTable& table, const std::vector<std::uint64_t>& parts = {});
  // Where each point mesh lies in the one vertex and index buffer the GPU sampler's polygon plants
  // are drawn from (zeros for other meshes): its first index and base vertex.
  struct DrawPlace {
    GLuint first_index = 0;
    GLint base_vertex = 0;
  };
  const std::vector<DrawPlace>& point_mesh_places() const { return places_; }
  // Puts the point meshes into the one vertex and index buffer (point_mesh_places) that
  // draw_chosen draws from: once, before the first draw_chosen.
  void gather_point_meshes();
  // Plants a GpuSampler chose as polygons (GpuSampler::polygon_draws, select_casters), in one
  // indirect multi-draw, for programs built with PLANT_INDEX (shaders/instance.glsl); `mode` as
  // for draw().
  void draw_chosen(const PlantDraws& draws, GLenum mode = GL_TRIANGLES) const;
  // The same plants, each triangle with its neighbours (GL_TRIANGLES_ADJACENCY), from draws whose
  // index counts and first indices count six indices a triangle (AdjacencyDraw makes them).
  void draw_chosen_with_adjacency(const PlantDraws& adjacency_draws) const;

 private:
  struct Range {
    GLuint first = 0;
    GLsizei count = 0;
  };
  struct Mesh {
    gl::Buffer vertices;
    std::optional<gl::Buffer> surfaces;  // texture coordinates and materials, of a mesh with materials
    gl::Buffer indices;
    std::optional<gl::Buffer> adjacency;  // six indices a triangle (draw_with_adjacency)
    GLsizei vertex_count = 0, index_count = 0;
    bool point_mesh = false;
    // Index ranges of its polygon parts (a point mesh), or of its chunks (a large other mesh).
    std::vector<Range> parts;
    std::vector<shadow::Box> chunk_boxes;  // a chunk's bounds, in the mesh's frame
    std::optional<pointgen::TriangleMesh> replaced;  // replace_mesh's, its indices in the order drawn
  };
  struct Group {
    gl::VertexArray vertex_array;
    gl::Buffer instances;
    std::size_t mesh = 0;
    GLsizei instance_count = 0;  // the table's: the buffer's first instances
    // The chosen parts: the buffer's instances drawn whole (the table's when it has no parts),
    // and per polygon part the range of those that draw it (empty without parts).
    Range whole;
    std::vector<Range> part_instances;
    std::size_t capacity = 0;
    std::optional<glm::mat4x3> only_transform;  // of the group's one instance
  };
  // `split`: the mesh's index list in the order drawn and its parts; none: drawn_split's.
  Mesh make_mesh(const pointgen::TriangleMesh& mesh, bool point_mesh, std::optional<pointgen::TriangleSplit> split = std::nullopt) const;
  void add_adjacency(std::size_t mesh, const pointgen::TriangleMesh& from);
  // The index ranges of a group's instances that `view` needs: its mesh's chunks whose boxes reach
  // it (neighbouring ranges joined), or the whole list.
  std::vector<Range> ranges_in_view(const Group& group, const std::optional<glm::mat4>& view) const;
  // Draws `ranges` of the bound vertex array's index list, which holds `per_index` indices for
  // each of a triangle list's (2: neighbours' lists), of `instances` of it.
  static void draw_ranges(GLenum mode, std::span<const Range> ranges, GLuint per_index, Range instances);
  static void set_vertex_attributes(GLuint vertex_array, GLuint vertices, GLuint indices, GLuint surfaces);
  void multi_draw_chosen(const PlantDraws& draws, GLenum mode) const;
  void gather_adjacency();  // the point meshes' neighbours, laid out as their indices in Chosen
  static void set_attributes(GLuint vertex_array, const Mesh& mesh, GLuint instances);
  void reserve(Group& group, std::size_t instances);
  SurfaceTextures textures_;
  std::vector<Mesh> meshes_;
  std::vector<Group> groups_;
  std::vector<DrawPlace> places_;
  GLsizei point_mesh_vertices_ = 0, point_mesh_indices_ = 0;  // in all point meshes
  // The point meshes in one buffer each, for draw_chosen (gather_point_meshes).
  struct Chosen {
    gl::Buffer vertices, indices;
    std::optional<gl::Buffer> surfaces;  // when a mesh has materials
    // Six indices a triangle, each point mesh's at twice its first index (draw_chosen_with_adjacency).
    std::optional<gl::Buffer> adjacency;
    gl::VertexArray vertex_array;
  };
  std::unique_ptr<Chosen> chosen_;
};

}  // namespace ecoview
