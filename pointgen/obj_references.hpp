#pragma once
#include <string>

namespace pointgen {

// An OBJ file declares no counts, but its faces refer to positions, texture coordinates and
// normals by number: from 1 among all of the file's (OpenMesh reads them all first), or from -1
// back among those before the face. OpenMesh drops a face with a bad position reference with only
// a log line, ignores bad others, and drops a vertex it cannot parse. This throws FileError, with
// the line, on any of them.
void check_obj_references(const std::string& path, const std::string& bytes);

}  // namespace pointgen
