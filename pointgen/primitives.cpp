#include "pointgen/primitives.hpp"

#include <glm/gtc/constants.hpp>

namespace pointgen {
namespace {

void add_vertex(TriangleMesh& mesh, const glm::vec3& position, const glm::vec3& normal) {
  mesh.positions.push_back(position);
  mesh.normals.push_back(normal);
  mesh.colors.push_back(glm::vec3(1.0f));
}

// Two triangles over four vertices already added, in counter-clockwise order seen from outside.
void add_quad(TriangleMesh& mesh, std::uint32_t first) {
  for (std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + k);
}

}  // namespace

TriangleMesh unit_box() {
  TriangleMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      glm::vec3 n(0.0f);
      n[axis] = sign;
      // u, v span the face so that u x v = n (counter-clockwise seen from outside).
      glm::vec3 u(0.0f), v(0.0f);
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = sign;
      const glm::vec3 c = 0.5f * n;
      const auto first = static_cast<std::uint32_t>(mesh.positions.size());
      add_vertex(mesh, c - 0.5f * u - 0.5f * v, n);
      add_vertex(mesh, c + 0.5f * u - 0.5f * v, n);
      add_vertex(mesh, c + 0.5f * u + 0.5f * v, n);
      add_vertex(mesh, c - 0.5f * u + 0.5f * v, n);
      add_quad(mesh, first);
    }
  }
  return mesh;
}

TriangleMesh unit_sphere(int slices, int stacks) {
  TriangleMesh mesh;
  for (int j = 0; j <= stacks; ++j) {
    const float theta = glm::pi<float>() * static_cast<float>(j) / static_cast<float>(stacks);
    for (int i = 0; i <= slices; ++i) {
      const float phi = glm::two_pi<float>() * static_cast<float>(i) / static_cast<float>(slices);
      const glm::vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta),
                        -std::sin(theta) * std::sin(phi));
      add_vertex(mesh, p, p);
    }
  }
  const auto row = static_cast<std::uint32_t>(slices + 1);
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const std::uint32_t a = static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
      const std::uint32_t b = a + row;
      mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  return mesh;
}

TriangleMesh unit_plane(int cells) {
  TriangleMesh mesh;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      const float x = static_cast<float>(i) / static_cast<float>(cells) - 0.5f;
      const float z = static_cast<float>(j) / static_cast<float>(cells) - 0.5f;
      add_vertex(mesh, glm::vec3(x, 0.0f, z), up);
    }
  }
  const auto row = static_cast<std::uint32_t>(cells + 1);
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const std::uint32_t a = static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
      const std::uint32_t b = a + row;  // the vertex at larger z, towards the viewer of +Y
      mesh.indices.insert(mesh.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
  }
  return mesh;
}

}  // namespace pointgen
