#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <functional>
#include <optional>
#include <string>

namespace pointgen {

// Returns the bytes of a file, or nothing when it does not exist; throws FileError naming the file
// when it is there but cannot be used (read_input_file's refusals). Lets one loader read from disk
// and from the resources embedded in the binary alike.
using ReadFile = std::function<std::optional<std::string>(const std::string& path)>;

// Takes one line about a file for the user: what of it is not used.
using Note = std::function<void(const std::string& line)>;

// Loads a triangle mesh from glTF (.gltf, .glb) or OpenMesh's formats (.obj, .ply, .off), baking
// node transforms into the vertices; glTF base-colour textures (PNG, JPEG) and alpha masks become
// the mesh's materials. Throws FileError naming the file on anything malformed (an image that
// cannot be decoded too, by its index). `note` hears what a file has that is not used (skins,
// animations, morph targets, extensions).
TriangleMesh load_mesh_file(const std::string& path, const ReadFile& read, const Note& note = {});

// What load_mesh_file does per format; `bytes` is the content of `path`.
TriangleMesh load_gltf(const std::string& path, const std::string& bytes, const ReadFile& read, const Note& note = {});
TriangleMesh load_openmesh_format(const std::string& path, const std::string& bytes);

}  // namespace pointgen
