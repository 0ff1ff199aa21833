#include "pointgen/mesh_builder.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace pointgen {

struct MeshBuilder::Impl {
  struct Traits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3f;
    using Normal = OpenMesh::Vec3f;
    using Color = OpenMesh::Vec3f;
    VertexAttributes(OpenMesh::Attributes::Normal | OpenMesh::Attributes::Color);
    FaceAttributes(OpenMesh::Attributes::Normal);
  };
  using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;
  Mesh mesh;

  OpenMesh::VertexHandle vertex(const glm::vec3& p, const glm::vec3& color) {
    const auto v = mesh.add_vertex({p.x, p.y, p.z});
    mesh.set_color(v, {color.r, color.g, color.b});
    return v;
  }
  void triangle(OpenMesh::VertexHandle a, OpenMesh::VertexHandle b, OpenMesh::VertexHandle c) {
    mesh.add_face(a, b, c);
  }
  // A grid of rows x columns vertices made into quads; columns wrap around when `closed`.
  void grid(const std::vector<OpenMesh::VertexHandle>& v, int rows, int columns, bool closed) {
    const int quads = closed ? columns : columns - 1;
    for (int r = 0; r + 1 < rows; ++r) {
      for (int c = 0; c < quads; ++c) {
        const auto at = [&](int rr, int cc) { return v[static_cast<std::size_t>(rr * columns + cc % columns)]; };
        triangle(at(r, c), at(r, c + 1), at(r + 1, c + 1));
        triangle(at(r, c), at(r + 1, c + 1), at(r + 1, c));
      }
    }
  }
};

namespace {

// Two unit vectors perpendicular to `axis` and to each other, u x v = axis.
void frame(const glm::vec3& axis, glm::vec3& u, glm::vec3& v) {
  u = glm::normalize(std::abs(axis.y) < 0.9f ? glm::cross(glm::vec3(0, 1, 0), axis) : glm::cross(glm::vec3(1, 0, 0), axis));
  v = glm::cross(axis, u);
}

}  // namespace

MeshBuilder::MeshBuilder() : impl_(std::make_unique<Impl>()) {}
MeshBuilder::~MeshBuilder() = default;

void MeshBuilder::tube(const glm::vec3& a, const glm::vec3& b, float ra, float rb, int sides, const glm::vec3& color,
                       bool capped) {
  const glm::vec3 axis = b - a;
  if (glm::length(axis) <= 0.0f) return;
  glm::vec3 u, v;
  frame(glm::normalize(axis), u, v);
  std::vector<OpenMesh::VertexHandle> ring;
  for (int end = 0; end < 2; ++end) {
    for (int i = 0; i < sides; ++i) {
      const float phi = glm::two_pi<float>() * static_cast<float>(i) / static_cast<float>(sides);
      const glm::vec3 out = std::cos(phi) * u + std::sin(phi) * v;
      ring.push_back(impl_->vertex((end ? b : a) + (end ? rb : ra) * out, color));
    }
  }
  impl_->grid(ring, 2, sides, true);
  if (capped) {
    const auto top = impl_->vertex(b, color);
    const auto bottom = impl_->vertex(a, color);
    for (int i = 0; i < sides; ++i) {
      const int j = (i + 1) % sides;
      impl_->triangle(ring[static_cast<std::size_t>(sides + i)], ring[static_cast<std::size_t>(sides + j)], top);
      impl_->triangle(ring[static_cast<std::size_t>(j)], ring[static_cast<std::size_t>(i)], bottom);
    }
  }
}

void MeshBuilder::lathe(const std::vector<glm::vec2>& profile, int sides, const glm::vec3& color,
                        const glm::mat4& transform) {
  std::vector<OpenMesh::VertexHandle> v;
  for (const glm::vec2& p : profile) {
    for (int i = 0; i < sides; ++i) {
      const float phi = glm::two_pi<float>() * static_cast<float>(i) / static_cast<float>(sides);
      // Counter-clockwise seen from +Y, so quads face outwards.
      const glm::vec4 local(p.x * std::cos(phi), p.y, -p.x * std::sin(phi), 1.0f);
      v.push_back(impl_->vertex(glm::vec3(transform * local), color));
    }
  }
  impl_->grid(v, static_cast<int>(profile.size()), sides, true);
}

void MeshBuilder::ellipsoid(const glm::mat4& transform, const glm::vec3& color, int slices, int stacks) {
  std::vector<glm::vec2> profile;
  for (int j = 0; j <= stacks; ++j) {
    const float theta = glm::pi<float>() * (1.0f - static_cast<float>(j) / static_cast<float>(stacks));
    profile.emplace_back(std::sin(theta), std::cos(theta));
  }
  lathe(profile, slices, color, transform);
}

void MeshBuilder::box(const glm::mat4& transform, const glm::vec3& color) {
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      glm::vec3 n(0.0f), u(0.0f), v(0.0f);
      n[axis] = sign;
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = sign;
      const glm::vec3 c = 0.5f * n;
      std::vector<glm::vec3> corners;
      for (const glm::vec2 k : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        corners.push_back(glm::vec3(transform * glm::vec4(c + 0.5f * k.x * u + 0.5f * k.y * v, 1.0f)));
      }
      polygon(corners, color);
    }
  }
}

void MeshBuilder::leaf(const glm::vec3& base, const glm::vec3& along, const glm::vec3& side, float length, float width,
                       const glm::vec3& color) {
  const glm::vec3 a = glm::normalize(along), s = glm::normalize(side);
  polygon({base, base + 0.45f * length * a - 0.5f * width * s, base + length * a, base + 0.45f * length * a + 0.5f * width * s},
          color);
}

void MeshBuilder::strip(const std::vector<glm::vec3>& spine, const std::vector<float>& widths, const glm::vec3& side,
                        const glm::vec3& color) {
  std::vector<OpenMesh::VertexHandle> v;
  const glm::vec3 s = glm::normalize(side);
  for (std::size_t i = 0; i < spine.size(); ++i) {
    v.push_back(impl_->vertex(spine[i] - 0.5f * widths[i] * s, color));
    v.push_back(impl_->vertex(spine[i] + 0.5f * widths[i] * s, color));
  }
  impl_->grid(v, static_cast<int>(spine.size()), 2, false);
}

void MeshBuilder::polygon(const std::vector<glm::vec3>& corners, const glm::vec3& color) {
  std::vector<OpenMesh::VertexHandle> v;
  for (const glm::vec3& p : corners) v.push_back(impl_->vertex(p, color));
  for (std::size_t i = 2; i < v.size(); ++i) impl_->triangle(v[0], v[i - 1], v[i]);
}

TriangleMesh MeshBuilder::build() const {
  Impl::Mesh mesh = impl_->mesh;
  mesh.update_normals();
  TriangleMesh out;
  out.positions.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const auto& n = mesh.normal(v);
    const auto& c = mesh.color(v);
    out.positions.emplace_back(p[0], p[1], p[2]);
    const glm::vec3 normal(n[0], n[1], n[2]);
    out.normals.push_back(std::isfinite(normal.x) && glm::length(normal) > 0.5f ? normal : glm::vec3(0, 1, 0));
    out.colors.emplace_back(c[0], c[1], c[2]);
  }
  for (const auto f : mesh.faces()) {
    for (const auto v : mesh.fv_range(f)) out.indices.push_back(static_cast<std::uint32_t>(v.idx()));
  }
  return out;
}

}  // namespace pointgen
