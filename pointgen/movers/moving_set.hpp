#pragma once
#include "pointgen/instance_table.hpp"
#include "pointgen/movers/body.hpp"
#include "pointgen/movers/path.hpp"
#include "pointgen/placement/terrain.hpp"

#include <array>
#include <optional>
#include <vector>

namespace pointgen {

// One body going round a loop: where it starts (offset, metres), how fast (m/s), its size and
// its three colours (linear RGB, see BodyPart::color_slot).
struct Mover {
  std::size_t body = 0;
  std::size_t path = 0;
  float speed = 1.0f;
  float offset = 0.0f;
  float scale = 1.0f;
  std::array<glm::vec3, 3> colors{glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f)};
  std::uint64_t seed = 0;
};

// Crowds, herds and traffic: movers whose pose is a function of time alone, so frame t shows
// the same scene in any process. Each body part is one mesh, drawn instanced for all movers.
struct MovingSet {
  std::vector<Body> bodies;
  std::vector<LoopPath> paths;
  std::vector<Mover> movers;
  std::optional<Terrain> ground;  // movers walk on it when set; otherwise at their path's height

  // The part meshes, body by body, part by part: the order of the tables pose() returns.
  std::vector<TriangleMesh> part_meshes() const;
  // One table per part mesh with every mover of that body posed at time t (seconds); mesh
  // indices count from `first_mesh`.
  std::vector<InstanceTable> pose(double t, std::size_t first_mesh) const;
  // Bounds of every pose at any time.
  Bounds bounds() const;
};

// Builders of moving sets.
// People wandering in `region` (at height y), keeping out of `obstacles`.
MovingSet make_crowd(int count, const Rect& region, const std::vector<Rect>& obstacles, float y, std::uint64_t seed);
// Cows wandering slowly in `pasture` over a terrain, raised by y.
MovingSet make_herd(int count, const Terrain& ground, const Rect& pasture, float y, std::uint64_t seed);
// Cars round `loops` (rectangles at height y) and aeroplanes circling `center` at `altitude`.
MovingSet make_traffic(int cars, const std::vector<Rect>& loops, float y, int aeroplanes, const glm::vec3& center,
                       float radius, float altitude, std::uint64_t seed);

}  // namespace pointgen
