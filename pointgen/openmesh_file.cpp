// OBJ, PLY and OFF through OpenMesh's readers, from memory.
#include "pointgen/declared_counts.hpp"
#include "pointgen/file_error.hpp"
#include "pointgen/mesh_file.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace pointgen {
namespace {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

// OpenMesh reports problems on its own log streams; ours go into FileError instead.
void silence_openmesh_logs() {
  static const bool silenced = [] {
    omlog().disable();
    omout().disable();
    omerr().disable();
    return true;
  }();
  (void)silenced;
}

glm::vec3 to_glm(const OpenMesh::Vec3f& v) { return {v[0], v[1], v[2]}; }

}  // namespace

TriangleMesh load_openmesh_format(const std::string& path, const std::string& bytes) {
  silence_openmesh_logs();
  PolyMesh poly;
  poly.request_vertex_normals();
  poly.request_vertex_colors();
  OpenMesh::IO::Options options;
  options += OpenMesh::IO::Options::VertexNormal;
  options += OpenMesh::IO::Options::VertexColor;
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  check_declared_counts(path, ext, bytes);
  std::istringstream stream(bytes);
  bool ok = false;
  try {
    ok = OpenMesh::IO::read_mesh(poly, stream, ext, options);
  } catch (const std::bad_alloc&) {
    throw FileError(path, "cannot be read: the counts in it ask for more memory than there is (corrupt file?)");
  } catch (const std::exception& e) {
    throw FileError(path, std::string("cannot be read: ") + e.what());
  }
  if (!ok) throw FileError(path, "not a valid " + ext.substr(1) + " mesh");

  TriangleMesh mesh;
  const bool has_normals = options.check(OpenMesh::IO::Options::VertexNormal);
  const bool has_colors = options.check(OpenMesh::IO::Options::VertexColor);
  for (const auto v : poly.vertices()) {
    mesh.positions.push_back(to_glm(poly.point(v)));
    if (has_normals) mesh.normals.push_back(glm::normalize(to_glm(poly.normal(v))));
    const auto c = poly.color(v);
    mesh.colors.push_back(has_colors ? glm::vec3(c[0], c[1], c[2]) / 255.0f : glm::vec3(1.0f));
  }
  for (const auto f : poly.faces()) {  // fan-triangulate each polygon
    std::vector<std::uint32_t> loop;
    for (const auto v : poly.fv_range(f)) loop.push_back(static_cast<std::uint32_t>(v.idx()));
    for (std::size_t i = 2; i < loop.size(); ++i) {
      mesh.indices.insert(mesh.indices.end(), {loop[0], loop[i - 1], loop[i]});
    }
  }
  if (!has_normals) mesh.normals = vertex_normals(mesh.positions, mesh.indices);
  for (glm::vec3& n : mesh.normals) {
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) n = glm::vec3(0, 1, 0);
  }
  return mesh;
}

}  // namespace pointgen
