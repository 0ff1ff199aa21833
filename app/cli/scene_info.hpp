#pragma once
#include "app/scene/scene.hpp"

#include <string>

namespace ecoview {

// One line about a loaded scene for the user: instances, triangles if every instance were drawn
// as polygons, meshes, their textures' memory (when they have any), load time and this process's
// resident memory.
std::string describe_scene(const Scene& scene, double load_seconds);

// Resident memory of this process in MiB (0 where the system does not say).
double resident_mib();

}  // namespace ecoview
