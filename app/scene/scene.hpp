#pragma once
#include "pointgen/instance_table.hpp"
#include "pointgen/landscape/ground_chunks.hpp"
#include "pointgen/movers/moving_set.hpp"
#include "pointgen/triangle_mesh.hpp"
#include "shadow/box.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"

#include <string>
#include <vector>

namespace ecoview {

// Groups whose instances move: groups[first_group …] hold the set's part tables, posed anew for
// each frame's time.
struct Animation {
  pointgen::MovingSet set;
  std::size_t first_group = 0;
  std::size_t first_mesh = 0;
};

// A landscape whose plants are made where the camera is, frame by frame (pointgen::LandscapePool):
// its species' groups, groups[first_group …] (group_count()), start empty, and its ground mesh
// (pointgen::GroundChunks, made for the scene's camera) is made anew for each eye.
struct LandscapeSource {
  pointgen::LandscapeSpec spec;
  std::vector<float> reach;  // per layer: metres from the eye within which its cells are made
  std::size_t first_group = 0;
  std::size_t capacity = 0;  // the most plants held at once
  std::size_t ground_mesh = 0;
  pointgen::GroundChunks::Settings ground;
  float plant_reach = 0.0f;  // metres from where a plant stands that it may reach, at most
  // The species' groups: one a species for its cells made whole, then one a species for the far
  // blocks' plants (pointgen::LandscapePool::tables).
  std::size_t group_count() const;
  // Bounds of its ground and of every plant it may grow.
  shadow::Box bounds() const;
};

// A loaded scene: each mesh once, instances as transforms. Units are metres, +Y is up.
struct Scene {
  std::string name;  // the file or shipped scene it came from, for messages
  shadow::Camera camera;
  std::vector<shadow::Light> lights;
  std::vector<pointgen::TriangleMesh> meshes;
  // Meshes whose far instances are drawn as point samples (plants, people, animals); the others
  // (ground, buildings, vehicles, primitives) are always polygons.
  std::vector<bool> point_meshes;
  std::vector<pointgen::InstanceTable> groups;  // each drawn with one instanced call; moving ones posed at t = 0
  std::vector<Animation> animations;
  std::vector<LandscapeSource> landscapes;
  // The plants its landscapes stand for, had every cell been made; only those near the camera are.
  double landscape_plants = 0.0;
  // What the scene's files have that is not used, a line per file, for the user.
  std::vector<std::string> notes;

  // Bounds of everything at any time.
  shadow::Box bounds() const;
  // Triangles drawn when every instance is drawn as polygons.
  std::size_t triangle_count() const;
  std::size_t instance_count() const;
  // Whether any mesh may be drawn as points (a scene without one renders the same with points off).
  bool has_point_meshes() const;
  // Bytes of the meshes' textures, each counted once.
  std::size_t texture_bytes() const;
};

}  // namespace ecoview
