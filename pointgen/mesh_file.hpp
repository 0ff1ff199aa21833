#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <functional>
#include <optional>
#include <string>

namespace pointgen {

// Returns the bytes of a file, or nothing when it does not exist. Lets one loader read from disk
// and from the resources embedded in the binary alike.
using ReadFile = std::function<std::optional<std::string>(const std::string& path)>;

// Loads a triangle mesh from glTF (.gltf, .glb) or OpenMesh's formats (.obj, .ply, .off), baking
// node transforms into the vertices. Throws FileError naming the file on anything malformed.
TriangleMesh load_mesh_file(const std::string& path, const ReadFile& read);

// What load_mesh_file does per format; `bytes` is the content of `path`.
TriangleMesh load_gltf(const std::string& path, const std::string& bytes, const ReadFile& read);
TriangleMesh load_openmesh_format(const std::string& path, const std::string& bytes);

}  // namespace pointgen
