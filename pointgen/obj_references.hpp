#pragma once
#include "pointgen/mesh_file.hpp"

#include <string>

namespace pointgen {

// An OBJ file declares no counts, but its faces refer to positions, texture coordinates and
// normals by number: from 1 among all of the file's (OpenMesh reads them all first), or from -1
// back among those before the face. OpenMesh drops a face with a bad position reference with only
// a log line, ignores bad others, and drops a vertex it cannot parse. This throws FileError, with
// the line, on any of them.
void check_obj_references(const std::string& path, const std::string& bytes);

// An OBJ names material libraries ("mtllib a.mtl"), files beside it. ecoview does not use OBJ
// materials (OpenMesh makes them face colours, which are not asked for), yet OpenMesh's reader,
// reading from memory, opens each library by its bare name from the working directory: /dev/zero
// it reads forever. So a library is looked up beside the OBJ through `read`, one that is there but
// cannot be used (no regular file, too large) throws FileError naming the OBJ, the line and the
// library, and `note` hears that the libraries are ignored.
void check_material_libraries(const std::string& path, const std::string& bytes, const ReadFile& read, const Note& note);

// The OBJ's bytes with every "mtllib" line made a comment, so that OpenMesh opens no file.
std::string without_material_libraries(std::string bytes);

}  // namespace pointgen
