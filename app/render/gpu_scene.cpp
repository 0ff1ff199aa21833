#include "app/render/gpu_scene.hpp"

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
    instances.push_back({table.transforms[i], {glm::vec4(n[0], 0), glm::vec4(n[1], 0), glm::vec4(n[2], 0)},
                         glm::vec4(table.tints[i], 1)});
  }
  return instances;
}

void attribute(GLuint vao, GLuint location, GLuint binding, GLint size, GLuint offset) {
  glEnableVertexArrayAttrib(vao, location);
  glVertexArrayAttribFormat(vao, location, size, GL_FLOAT, GL_FALSE, offset);
  glVertexArrayAttribBinding(vao, location, binding);
}

}  // namespace

GpuScene::GpuScene(const Scene& scene) {
  for (const pointgen::TriangleMesh& mesh : scene.meshes) {
    std::vector<Vertex> vertices;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      vertices.push_back({mesh.positions[i], mesh.normals[i], mesh.colors[i]});
    }
    Mesh& m = meshes_.emplace_back();
    gl::store(m.vertices, vertices);
    gl::store(m.indices, mesh.indices);
    m.index_count = static_cast<GLsizei>(mesh.indices.size());
  }
  for (const pointgen::InstanceTable& group : scene.groups) {
    const std::vector<Instance> instances = instances_of(group);
    const Mesh& mesh = meshes_[group.mesh];
    Group& g = groups_.emplace_back();
    gl::store(g.instances, instances, GL_DYNAMIC_STORAGE_BIT);
    g.index_count = mesh.index_count;
    g.instance_count = static_cast<GLsizei>(instances.size());
    g.capacity = instances.size();

    const GLuint vao = g.vertex_array.name();
    glVertexArrayVertexBuffer(vao, 0, mesh.vertices.name(), 0, sizeof(Vertex));
    glVertexArrayVertexBuffer(vao, 1, g.instances.name(), 0, sizeof(Instance));
    glVertexArrayBindingDivisor(vao, 1, 1);
    glVertexArrayElementBuffer(vao, mesh.indices.name());
    attribute(vao, 0, 0, 3, offsetof(Vertex, position));
    attribute(vao, 1, 0, 3, offsetof(Vertex, normal));
    attribute(vao, 2, 0, 3, offsetof(Vertex, color));
    for (GLuint c = 0; c < 4; ++c) attribute(vao, 3 + c, 1, 4, offsetof(Instance, model) + c * sizeof(glm::vec4));
    for (GLuint c = 0; c < 3; ++c) attribute(vao, 7 + c, 1, 3, offsetof(Instance, normal_matrix) + c * sizeof(glm::vec4));
    attribute(vao, 10, 1, 3, offsetof(Instance, color));
  }
}

void GpuScene::update(std::size_t group, const pointgen::InstanceTable& table) {
  Group& g = groups_[group];
  const std::vector<Instance> instances = instances_of(table);
  g.instance_count = static_cast<GLsizei>(std::min(instances.size(), g.capacity));
  glNamedBufferSubData(g.instances.name(), 0, static_cast<GLsizeiptr>(static_cast<std::size_t>(g.instance_count) * sizeof(Instance)),
                       instances.data());
}

void GpuScene::draw(GLenum mode) const {
  for (const Group& group : groups_) {
    if (group.instance_count == 0) continue;
    glBindVertexArray(group.vertex_array.name());
    glDrawElementsInstanced(mode, group.index_count, GL_UNSIGNED_INT, nullptr, group.instance_count);
  }
  glBindVertexArray(0);
}

}  // namespace ecoview
