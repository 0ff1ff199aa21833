#pragma once
#include <string>

namespace pointgen {

// OFF and PLY files declare counts (vertices, faces, vertices per face) that OpenMesh's readers
// trust: they reserve memory and loop by them, so one corrupt number can ask for gigabytes. This
// checks every count against what the file can hold before OpenMesh reads it, and that OFF
// vertices are numbers, and throws FileError on one that cannot be right. `ext` is ".off" or
// ".ply"; other formats pass.

// Whether `text` starts with three numbers finite as floats. (OpenMesh's readers drop a vertex
// they cannot parse, so that the faces after it refer to the wrong ones or to none.)
bool three_finite_numbers(const char* text);
void check_declared_counts(const std::string& path, const std::string& ext, const std::string& bytes);

}  // namespace pointgen
