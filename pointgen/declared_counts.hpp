#pragma once
#include <string>

namespace pointgen {

// OFF and PLY files declare counts (vertices, faces, vertices per face) that OpenMesh's readers
// trust: they reserve memory and loop by them, so one corrupt number can ask for gigabytes. This
// checks every count against what the file can hold before OpenMesh reads it, and an OBJ file's
// face references against what comes before them, and throws FileError on one that cannot be
// right. `ext` is ".off", ".ply" or ".obj"; other formats pass.
void check_declared_counts(const std::string& path, const std::string& ext, const std::string& bytes);

}  // namespace pointgen
