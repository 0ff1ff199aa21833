#include "pointgen/mesh_file.hpp"

#include "pointgen/file_error.hpp"
#include "pointgen/obj_references.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace pointgen {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void check_mesh(const std::string& path, const TriangleMesh& mesh) {
  if (mesh.indices.empty()) throw FileError(path, "contains no triangles");
  for (const glm::vec3& p : mesh.positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw FileError(path, "a vertex position is NaN or infinite");
    }
  }
}

}  // namespace

TriangleMesh load_mesh_file(const std::string& path, const ReadFile& read, const Note& note) {
  const std::optional<std::string> bytes = read(path);
  if (!bytes) throw FileError(path, "no such file");
  // OpenMesh reserves for counts an empty file never gave: it is refused before any reader sees it.
  if (bytes->find_first_not_of(" \t\r\n") == std::string::npos) throw FileError(path, "is empty");
  const std::string ext = lower_extension(path);
  TriangleMesh mesh;
  if (ext == ".gltf" || ext == ".glb") {
    mesh = load_gltf(path, *bytes, read, note);
  } else if (ext == ".obj" || ext == ".ply" || ext == ".off") {
    if (ext == ".obj") check_material_libraries(path, *bytes, read, note);
    mesh = load_openmesh_format(path, *bytes);
  } else {
    throw FileError(path, "unknown mesh format '" + ext + "' (use .gltf, .glb, .obj, .ply or .off)");
  }
  check_mesh(path, mesh);
  return mesh;
}

}  // namespace pointgen
