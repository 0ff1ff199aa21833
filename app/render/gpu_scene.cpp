#include "app/render/gpu_scene.hpp"

#include "app/errors.hpp"
#include "app/render/buffer_texture_units.hpp"

#include "pointgen/sampling/mesh_parts.hpp"
#include "pointgen/triangle_adjacency.hpp"

#include <algorithm>

namespace ecoview {
namespace {

struct Vertex {
  glm::vec3 position, normal, color;
};

struct Instance {
  glm::mat4 model;
  glm::vec4 normal_matrix[3];  // columns of mat3(transpose(inverse(model))), padded
  glm::vec4 color;
};

std::vector<Instance> instances_of(const pointgen::InstanceTable& table) {
  std::vector<Instance> instances;
  instances.reserve(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    const glm::mat3 n = glm::transpose(glm::inverse(glm::mat3(table.transforms[i])));
    instances.push_back({table.transform(i), {glm::vec4(n[0], 0), glm::vec4(n[1], 0), glm::vec4(n[2], 0)},
                         glm::vec4(table.tint(i), 1)});
  }
  return instances;
}

// A mesh of more triangles than this, other than a point mesh, is drawn by chunks: a cell each of
// a grid of chunk_cells³ over its bounds (the ecosystem's terrain: 131,072 triangles in chunks of
// about 31 m a side), so that a view draws those that reach it alone: a tile of a paged map
// covers a few metres, and its silhouette pass shades every triangle drawn.
constexpr std::size_t chunked_triangles = 16384;
constexpr int chunk_cells = 8;

// A mesh's triangles in the order they are drawn: a point mesh's by the polygon parts the sampler
// chooses (PointSamples makes the same split), a large other mesh's by chunks; none for the rest.
std::optional<pointgen::TriangleSplit> drawn_split(const pointgen::TriangleMesh& mesh, bool point_mesh) {
  if (point_mesh) return pointgen::split_triangles(mesh);
  if (mesh.triangle_count() > chunked_triangles) return pointgen::split_triangles(mesh, chunk_cells);
  return std::nullopt;
}

std::optional<glm::mat4x3> only_transform(const pointgen::InstanceTable& table) {
  if (table.size() != 1) return std::nullopt;
  return table.transforms.front();
}

void attribute(GLuint vao, GLuint location, GLuint binding, GLint size, GLuint offset) {
  glEnableVertexArrayAttrib(vao, location);
  glVertexArrayAttribFormat(vao, location, size, GL_FLOAT, GL_FALSE, offset);
  glVertexArrayAttribBinding(vao, location, binding);
}

}  // namespace

GpuScene::GpuScene(const Scene& scene) : textures_(scene.meshes) {
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    Mesh& m = meshes_.emplace_back(make_mesh(scene.meshes[i], scene.point_meshes[i]));
    places_.emplace_back();
    if (m.point_mesh) {
      places_.back() = {static_cast<GLuint>(point_mesh_indices_), point_mesh_vertices_};
      point_mesh_indices_ += m.index_count;
      point_mesh_vertices_ += m.vertex_count;
    }
  }
  for (const pointgen::InstanceTable& group : scene.groups) {
    const Mesh& mesh = meshes_[group.mesh];
    // A point mesh's instances come with each pass, those it draws as polygons (update): none at
    // load (at 10^6 plants they would take 128 MB here and as much again on the way).
    const std::vector<Instance> instances = mesh.point_mesh ? std::vector<Instance>{} : instances_of(group);
    Group& g = groups_.emplace_back();
    gl::store(g.instances, instances, GL_DYNAMIC_STORAGE_BIT);
    g.mesh = group.mesh;
    g.instance_count = static_cast<GLsizei>(instances.size());
    g.whole = {0, g.instance_count};
    g.capacity = instances.size();
    g.only_transform = only_transform(group);

    set_attributes(g.vertex_array.name(), mesh, g.instances.name());
  }
}

GpuScene::Mesh GpuScene::make_mesh(const pointgen::TriangleMesh& mesh, bool point_mesh, std::optional<pointgen::TriangleSplit> split) const {
  std::vector<Vertex> vertices;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    vertices.push_back({mesh.positions[v], mesh.normals[v], mesh.colors[v]});
  }
  Mesh m;
  gl::store(m.vertices, vertices);
  if (!mesh.materials.empty()) gl::store(m.surfaces.emplace(), textures_.vertex_surfaces(mesh));
  m.vertex_count = static_cast<GLsizei>(vertices.size());
  m.index_count = static_cast<GLsizei>(mesh.indices.size());
  m.point_mesh = point_mesh;
  if (!split) split = drawn_split(mesh, m.point_mesh);
  gl::store(m.indices, split ? split->indices : mesh.indices);
  if (!split) return m;
  for (const pointgen::PolygonPart& part : split->parts) {
    m.parts.push_back({part.first_index, static_cast<GLsizei>(part.index_count)});
    if (m.point_mesh) continue;
    m.chunk_boxes.emplace_back().add(part.center - part.half_size);
    m.chunk_boxes.back().add(part.center + part.half_size);
  }
  return m;
}

void GpuScene::replace_mesh(std::size_t mesh, const pointgen::TriangleMesh& with, const std::vector<pointgen::PolygonPart>& chunks) {
  Mesh& m = meshes_[mesh];
  if (m.point_mesh) throw RuntimeFailure("a point mesh cannot be replaced");
  const bool adjacency = m.adjacency.has_value();
  m = make_mesh(with, false, pointgen::TriangleSplit{with.indices, chunks});
  m.replaced = with;
  if (adjacency) add_adjacency(mesh, with);
  for (Group& group : groups_) {
    if (group.mesh == mesh) set_attributes(group.vertex_array.name(), m, group.instances.name());
  }
}

// `surfaces` 0: the mesh has no materials, and attribute 11 keeps GL's default (0, 0, 0, 1): no
// texture, an alpha threshold the white texel passes.
void GpuScene::set_vertex_attributes(GLuint vao, GLuint vertices, GLuint indices, GLuint surfaces) {
  glVertexArrayVertexBuffer(vao, 0, vertices, 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, indices);
  attribute(vao, 0, 0, 3, offsetof(Vertex, position));
  attribute(vao, 1, 0, 3, offsetof(Vertex, normal));
  attribute(vao, 2, 0, 3, offsetof(Vertex, color));
  if (surfaces == 0) return;
  glVertexArrayVertexBuffer(vao, 2, surfaces, 0, sizeof(glm::vec4));
  attribute(vao, 11, 2, 4, 0);
}

void GpuScene::set_attributes(GLuint vao, const Mesh& mesh, GLuint instances) {
  set_vertex_attributes(vao, mesh.vertices.name(), mesh.indices.name(), mesh.surfaces ? mesh.surfaces->name() : 0);
  glVertexArrayVertexBuffer(vao, 1, instances, 0, sizeof(Instance));
  glVertexArrayBindingDivisor(vao, 1, 1);
  for (GLuint c = 0; c < 4; ++c) attribute(vao, 3 + c, 1, 4, offsetof(Instance, model) + c * sizeof(glm::vec4));
  for (GLuint c = 0; c < 3; ++c) attribute(vao, 7 + c, 1, 3, offsetof(Instance, normal_matrix) + c * sizeof(glm::vec4));
  attribute(vao, 10, 1, 3, offsetof(Instance, color));
}

void GpuScene::gather_point_meshes() {
  chosen_ = std::make_unique<Chosen>();
  glNamedBufferStorage(chosen_->vertices.name(), static_cast<GLsizeiptr>(std::max(point_mesh_vertices_, 1)) * sizeof(Vertex), nullptr, 0);
  glNamedBufferStorage(chosen_->indices.name(), static_cast<GLsizeiptr>(std::max(point_mesh_indices_, 1)) * sizeof(GLuint), nullptr, 0);
  if (textures_.any()) {
    // Where a point mesh has no materials: no texture (code 0), no mask (keep scale -1).
    const std::vector<glm::vec4> none(static_cast<std::size_t>(std::max(point_mesh_vertices_, 1)), glm::vec4(0.0f, 0.0f, 0.0f, -1.0f));
    gl::store(chosen_->surfaces.emplace(), none);
  }
  for (std::size_t m = 0; m < meshes_.size(); ++m) {
    if (!meshes_[m].point_mesh) continue;
    if (meshes_[m].surfaces) {
      glCopyNamedBufferSubData(meshes_[m].surfaces->name(), chosen_->surfaces->name(), 0,
                               static_cast<GLintptr>(places_[m].base_vertex) * static_cast<GLintptr>(sizeof(glm::vec4)),
                               static_cast<GLsizeiptr>(meshes_[m].vertex_count) * static_cast<GLsizeiptr>(sizeof(glm::vec4)));
    }
    glCopyNamedBufferSubData(meshes_[m].vertices.name(), chosen_->vertices.name(), 0,
                             static_cast<GLintptr>(places_[m].base_vertex) * static_cast<GLintptr>(sizeof(Vertex)),
                             static_cast<GLsizeiptr>(meshes_[m].vertex_count) * static_cast<GLsizeiptr>(sizeof(Vertex)));
    glCopyNamedBufferSubData(meshes_[m].indices.name(), chosen_->indices.name(), 0,
                             static_cast<GLintptr>(places_[m].first_index) * static_cast<GLintptr>(sizeof(GLuint)),
                             static_cast<GLsizeiptr>(meshes_[m].index_count) * static_cast<GLsizeiptr>(sizeof(GLuint)));
  }
  // An instance is a plant index (shaders/instance.glsl, PLANT_INDEX), from the list a draw names.
  const GLuint vao = chosen_->vertex_array.name();
  set_vertex_attributes(vao, chosen_->vertices.name(), chosen_->indices.name(),
                        chosen_->surfaces ? chosen_->surfaces->name() : 0);
  glVertexArrayBindingDivisor(vao, 1, 1);
  glEnableVertexArrayAttrib(vao, 3);
  glVertexArrayAttribIFormat(vao, 3, 1, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(vao, 3, 1);
  if (!meshes_.empty() && meshes_.front().adjacency) gather_adjacency();
}

void GpuScene::gather_adjacency() {
  glNamedBufferStorage(chosen_->adjacency.emplace().name(), 2 * static_cast<GLsizeiptr>(std::max(point_mesh_indices_, 1)) * sizeof(GLuint), nullptr, 0);
  for (std::size_t m = 0; m < meshes_.size(); ++m) {
    if (!meshes_[m].point_mesh) continue;
    glCopyNamedBufferSubData(meshes_[m].adjacency->name(), chosen_->adjacency->name(), 0,
                             2 * static_cast<GLintptr>(places_[m].first_index) * static_cast<GLintptr>(sizeof(GLuint)),
                             2 * static_cast<GLsizeiptr>(meshes_[m].index_count) * static_cast<GLsizeiptr>(sizeof(GLuint)));
  }
}

void GpuScene::draw_chosen(const PlantDraws& draws, GLenum mode) const {
  if (!chosen_ || draws.command_count == 0) return;
  multi_draw_chosen(draws, mode);
}

void GpuScene::draw_chosen_with_adjacency(const PlantDraws& adjacency_draws) const {
  if (!chosen_ || adjacency_draws.command_count == 0) return;
  if (!chosen_->adjacency) throw RuntimeFailure("draw_chosen_with_adjacency before add_adjacency");
  const GLuint vao = chosen_->vertex_array.name();
  glVertexArrayElementBuffer(vao, chosen_->adjacency->name());
  multi_draw_chosen(adjacency_draws, GL_TRIANGLES_ADJACENCY);
  glVertexArrayElementBuffer(vao, chosen_->indices.name());
}

void GpuScene::multi_draw_chosen(const PlantDraws& draws, GLenum mode) const {
  if (draws.draw_counts == 0) throw RuntimeFailure("plant draws without their count (DrawnCommands::keep_drawn)");
  glVertexArrayVertexBuffer(chosen_->vertex_array.name(), 1, draws.plant_indices, 0, sizeof(GLuint));
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, draws.commands);
  glBindTextureUnit(instance_texels_unit, draws.plants);
  glBindBuffer(GL_PARAMETER_BUFFER_ARB, draws.draw_counts);
  textures_.bind();
  glBindVertexArray(chosen_->vertex_array.name());
  glMultiDrawElementsIndirectCountARB(mode, GL_UNSIGNED_INT, reinterpret_cast<const void*>(draws.first_command * GpuScene::command_bytes),
                                      static_cast<GLintptr>(draws.count_slot * sizeof(GLuint)),
                                      static_cast<GLsizei>(draws.command_count), 0);
  glBindVertexArray(0);
  glBindBuffer(GL_PARAMETER_BUFFER_ARB, 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

void GpuScene::add_adjacency(const Scene& scene) {
  for (std::size_t m = 0; m < meshes_.size(); ++m) {
    if (!meshes_[m].adjacency) add_adjacency(m, meshes_[m].replaced ? *meshes_[m].replaced : scene.meshes[m]);
  }
  if (chosen_ && !chosen_->adjacency) gather_adjacency();
}

void GpuScene::add_adjacency(std::size_t mesh, const pointgen::TriangleMesh& from) {
  // In the order of the index list drawn, so that a part's range of it, doubled, is that part's.
  pointgen::TriangleMesh drawn = from;
  std::optional<pointgen::TriangleSplit> split = meshes_[mesh].replaced ? std::nullopt : drawn_split(drawn, meshes_[mesh].point_mesh);
  if (split) drawn.indices = std::move(split->indices);
  gl::store(meshes_[mesh].adjacency.emplace(), pointgen::adjacency_indices(drawn));
}

void GpuScene::draw_with_adjacency(const std::optional<glm::mat4>& view) const {
  if (meshes_.empty() || !meshes_.front().adjacency) throw RuntimeFailure("draw_with_adjacency before add_adjacency");
  textures_.bind();
  for (const Group& group : groups_) {
    const Mesh& mesh = meshes_[group.mesh];
    if (group.instance_count == 0 || mesh.index_count == 0) continue;
    // The group's vertex array with the neighbours' indices for this draw: one array, so that
    // instance buffers it grows (reserve) stay bound wherever it draws.
    const GLuint vao = group.vertex_array.name();
    glVertexArrayElementBuffer(vao, mesh.adjacency->name());
    glBindVertexArray(vao);
    draw_ranges(GL_TRIANGLES_ADJACENCY, ranges_in_view(group, view), 2, {0, group.instance_count});
    glBindVertexArray(0);
    glVertexArrayElementBuffer(vao, mesh.indices.name());
  }
}

void GpuScene::draw_ranges(GLenum mode, std::span<const Range> ranges, GLuint per_index, Range instances) {
  if (instances.count == 0) return;
  const auto offset = [&](const Range& range) {
    return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(per_index * range.first) * sizeof(GLuint));
  };
  if (ranges.size() > 1 && instances.first == 0 && instances.count == 1) {
    // A mesh drawn once by its chunks: one call, as llvmpipe spends some microseconds on each.
    std::vector<GLsizei> counts;
    std::vector<const void*> offsets;
    for (const Range& range : ranges) {
      counts.push_back(static_cast<GLsizei>(per_index) * range.count);
      offsets.push_back(offset(range));
    }
    glMultiDrawElements(mode, counts.data(), GL_UNSIGNED_INT, offsets.data(), static_cast<GLsizei>(ranges.size()));
    return;
  }
  for (const Range& range : ranges) {
    if (range.count == 0) continue;
    glDrawElementsInstancedBaseInstance(mode, static_cast<GLsizei>(per_index) * range.count, GL_UNSIGNED_INT, offset(range), instances.count, instances.first);
  }
}

std::vector<GpuScene::Range> GpuScene::ranges_in_view(const Group& group, const std::optional<glm::mat4>& view) const {
  const Mesh& mesh = meshes_[group.mesh];
  if (!view || !group.only_transform || mesh.chunk_boxes.empty()) return {{0, mesh.index_count}};
  std::vector<Range> ranges;
  for (std::size_t c = 0; c < mesh.chunk_boxes.size(); ++c) {
    if (shadow::outside_view(shadow::transformed(mesh.chunk_boxes[c], *group.only_transform), *view)) continue;
    const Range chunk = mesh.parts[c];
    if (!ranges.empty() && ranges.back().first + static_cast<GLuint>(ranges.back().count) == chunk.first) {
      ranges.back().count += chunk.count;
    } else {
      ranges.push_back(chunk);
    }
  }
  return ranges;
}

std::size_t GpuScene::fixed_triangles(const std::optional<glm::mat4>& view) const {
  std::size_t triangles = 0;
  for (const Group& group : groups_) {
    if (meshes_[group.mesh].point_mesh) continue;
    for (const Range& range : ranges_in_view(group, view)) triangles += static_cast<std::size_t>(range.count / 3) * static_cast<std::size_t>(group.instance_count);
  }
  return triangles;
}

void GpuScene::reserve(Group& group, std::size_t instances) {
  if (instances <= group.capacity) return;
  group.capacity = std::max(instances, 2 * group.capacity);
  group.instances = gl::Buffer();
  glNamedBufferStorage(group.instances.name(), static_cast<GLsizeiptr>(group.capacity * sizeof(Instance)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glVertexArrayVertexBuffer(group.vertex_array.name(), 1, group.instances.name(), 0, sizeof(Instance));
}

void GpuScene::update(std::size_t group, const pointgen::InstanceTable& table, const std::vector<std::uint64_t>& parts) {
  Group& g = groups_[group];
  std::vector<Instance> instances = instances_of(table);
  const std::size_t n = instances.size();
  g.instance_count = static_cast<GLsizei>(n);
  g.whole = {0, g.instance_count};
  g.part_instances.clear();
  g.only_transform = only_transform(table);
  const std::vector<Range>& mesh_parts = meshes_[g.mesh].parts;
  if (parts.size() == n && n > 0 && !mesh_parts.empty()) {
    // After the table: the instances with every part drawn whole, then each part's.
    const std::uint64_t every_part = mesh_parts.size() >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << mesh_parts.size()) - 1;
    const auto all_parts = [&](std::uint64_t bits) { return (bits & every_part) == every_part; };
    const auto add_those = [&](auto chosen) {
      Range range{static_cast<GLuint>(instances.size()), 0};
      for (std::size_t i = 0; i < n; ++i) {
        if (chosen(parts[i])) instances.push_back(instances[i]);
      }
      range.count = static_cast<GLsizei>(instances.size() - range.first);
      return range;
    };
    g.whole = add_those(all_parts);
    for (std::size_t p = 0; p < mesh_parts.size(); ++p) {
      g.part_instances.push_back(add_those([&](std::uint64_t bits) { return !all_parts(bits) && (bits >> p & 1u); }));
    }
  }
  reserve(g, instances.size());
  glNamedBufferSubData(g.instances.name(), 0, static_cast<GLsizeiptr>(instances.size() * sizeof(Instance)), instances.data());
}

void GpuScene::draw(GLenum mode, const std::optional<glm::mat4>& view) const {
  textures_.bind();
  for (const Group& group : groups_) {
    const Mesh& mesh = meshes_[group.mesh];
    glBindVertexArray(group.vertex_array.name());
    draw_ranges(mode, ranges_in_view(group, view), 1, group.whole);
    for (std::size_t p = 0; p < group.part_instances.size(); ++p) draw_ranges(mode, {&mesh.parts[p], 1}, 1, group.part_instances[p]);
  }
  glBindVertexArray(0);
}

}  // namespace ecoview
