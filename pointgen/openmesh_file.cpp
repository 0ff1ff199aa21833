// OBJ, PLY and OFF through OpenMesh's readers, from memory.
#include "pointgen/declared_counts.hpp"
#include "pointgen/file_error.hpp"
#include "pointgen/mesh_file.hpp"
#include "pointgen/obj_references.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <sstream>

namespace pointgen {
namespace {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

// OpenMesh reports problems on its own log streams; ours go into FileError instead. Its readers
// skip a face that refers to a vertex the file lacks and say so only on omerr, so that stream is
// kept here to be read after each file. The streams are global: one file is read at a time.
std::mutex one_file_at_a_time;

std::ostringstream& openmesh_errors() {
  static std::ostringstream errors;
  static const bool redirected = [] {
    omlog().disable();
    omout().disable();
    omerr().disconnect(std::cerr);
    omerr().connect(errors);
    return true;
  }();
  (void)redirected;
  return errors;
}

// While it lives, what is written to std::cerr and std::clog goes into `text` instead: some of
// OpenMesh's readers write there directly, and a failure must be one line of ours.
class CaughtErrorStreams {
 public:
  CaughtErrorStreams() : cerr_(std::cerr.rdbuf(text.rdbuf())), clog_(std::clog.rdbuf(text.rdbuf())) {}
  ~CaughtErrorStreams() {
    std::cerr.rdbuf(cerr_);
    std::clog.rdbuf(clog_);
  }
  CaughtErrorStreams(const CaughtErrorStreams&) = delete;
  CaughtErrorStreams& operator=(const CaughtErrorStreams&) = delete;
  std::ostringstream text;

 private:
  std::streambuf* cerr_;
  std::streambuf* clog_;
};

// The first line OpenMesh wrote for the file just read, on either of its ways, as a clause of our
// message ("" when it wrote nothing).
std::string openmesh_said(const std::string& caught) {
  omerr().flush();
  std::string said = openmesh_errors().str() + caught;
  said = said.substr(0, said.find('\n'));
  return said.empty() ? "" : " (OpenMesh: " + said.substr(0, 120) + ")";
}

// Whether the reader of the file just read skipped faces with vertex indices the file lacks. (A
// non-manifold face it reports too, but adds with its vertices copied.)
bool skipped_bad_faces() {
  omerr().flush();
  const std::string errors = openmesh_errors().str();
  return errors.find("invalid vertex index") != std::string::npos || errors.find("invalid faces") != std::string::npos;
}

glm::vec3 to_glm(const OpenMesh::Vec3f& v) { return {v[0], v[1], v[2]}; }

}  // namespace

TriangleMesh load_openmesh_format(const std::string& path, const std::string& bytes) {
  const std::lock_guard lock(one_file_at_a_time);
  omerr().flush();  // what an earlier file left unflushed is not this one's
  openmesh_errors().str("");
  PolyMesh poly;
  poly.request_vertex_normals();
  poly.request_vertex_colors();
  OpenMesh::IO::Options options;
  options += OpenMesh::IO::Options::VertexNormal;
  options += OpenMesh::IO::Options::VertexColor;
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  check_declared_counts(path, ext, bytes);
  if (ext == ".obj") check_obj_references(path, bytes);
  std::istringstream stream(ext == ".obj" ? without_material_libraries(bytes) : bytes);
  bool ok = false;
  {
    const CaughtErrorStreams caught;
    try {
      ok = OpenMesh::IO::read_mesh(poly, stream, ext, options);
    } catch (const std::bad_alloc&) {
      throw FileError(path, "cannot be read: the counts in it ask for more memory than there is (corrupt file?)");
    } catch (const std::exception& e) {
      throw FileError(path, std::string("cannot be read: ") + e.what());
    }
    if (!ok) throw FileError(path, "not a valid " + ext.substr(1) + " mesh" + openmesh_said(caught.text.str()));
  }
  if (skipped_bad_faces()) throw FileError(path, "a face refers to a vertex the file does not have (corrupt file?)");

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
