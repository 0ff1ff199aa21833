#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <cstdint>
#include <vector>

namespace pointgen {

struct TerrainSpec {
  glm::vec2 center{0.0f};
  glm::vec2 size{200.0f};
  float relief = 10.0f;        // metres from the lowest to the highest point, about; centred on 0
  float feature = 80.0f;       // horizontal size of the largest hills, metres
  int resolution = 128;        // grid cells along the longer side
  std::uint64_t seed = 1;
  glm::vec3 low_color{0.20f, 0.33f, 0.08f};   // linear RGB in valleys
  glm::vec3 high_color{0.42f, 0.40f, 0.22f};  // on tops and steep slopes
};

// A height field over a rectangle, from fractal value noise on a grid. height() interpolates on
// the same triangles that mesh() draws, so what stands at height(x, z) stands on the drawn ground.
class Terrain {
 public:
  explicit Terrain(const TerrainSpec& spec);

  float height(float x, float z) const;  // clamped to the rectangle outside it
  TriangleMesh mesh() const;
  const TerrainSpec& spec() const { return spec_; }

 private:
  float grid(int i, int j) const { return heights_[static_cast<std::size_t>(j * (cells_.x + 1) + i)]; }

  TerrainSpec spec_;
  glm::ivec2 cells_;
  glm::vec2 origin_, cell_;
  std::vector<float> heights_;
};

}  // namespace pointgen
