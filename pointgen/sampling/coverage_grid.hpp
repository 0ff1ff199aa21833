#pragma once
#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <vector>

namespace pointgen {

// How much of a view is already covered, in screen tiles of a few pixels, as objects are added
// front to back: the sampler's occlusion model (docs/point_density.md, "Occlusion"). Each tile
// keeps its transmittance, the fraction of it through which objects behind can still be seen.
class CoverageGrid {
 public:
  // A rectangle in normalized device coordinates.
  struct Rect {
    glm::vec2 min, max;
    float area() const { return (max.x - min.x) * (max.y - min.y); }
  };

  CoverageGrid(const glm::mat4& view_projection, glm::ivec2 tiles);

  // The screen rectangle holding a box (its eight corners), or none when part of it lies behind the eye.
  std::optional<Rect> project(const std::array<glm::vec3, 8>& corners) const;
  // Square NDC units that one square metre facing the view covers at `point`.
  float ndc_area_per_square_metre(const glm::vec3& point) const;
  // Mean transmittance over the part of `rect` on screen (1 where nothing covers it yet).
  float transmittance(const Rect& rect) const;
  // Adds an object spread over `rect` that hides `opacity` (0..1) of what lies behind it.
  void cover(const Rect& rect, float opacity);

 private:
  // Calls visit(tile index, fraction of the tile inside rect) for each tile the rect overlaps.
  template <class Visit>
  void for_tiles(const Rect& rect, Visit visit) const;

  glm::mat4 view_projection_;
  glm::ivec2 tiles_;
  std::vector<float> transmittance_;
};

}  // namespace pointgen
