#pragma once
#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace pointgen {

// Where in a shadow map's view the camera sees surfaces that shadows may fall on: the view cut
// into tiles, each marked when a receiver (a point of the surface the camera saw) projects into it
// or into a neighbour. A caster darkens a receiver only where both project into the same texel, so
// one whose box covers no marked tile shadows nothing the camera sees, and the shadow sampler
// skips it (shadow caster culling; docs/point_density.md, "Receivers"). The test does not look at
// depth, so it holds for inverted lights too.
class ReceiverMask {
 public:
  static constexpr int tiles_per_side = 64;

  // `view_projection`: the shadow view's world → clip matrix; `receivers`: world points.
  ReceiverMask(const glm::mat4& view_projection, std::span<const glm::vec3> receivers);

  // Whether a box (its centre and half sizes in a frame that `transform` places) may shadow a
  // receiver: it covers a marked tile, or reaches behind the view's eye.
  bool may_shadow(const glm::vec3& center, const glm::vec3& half_size, const glm::mat4& transform) const;

 private:
  int marked_in(int x1, int y1, int x2, int y2) const;  // marked tiles in [x1, x2] x [y1, y2]

  glm::mat4 view_projection_;
  // Marked tiles summed over the rectangle from tile (0, 0) to each tile: (tiles + 1)² entries.
  std::vector<int> summed_;
};

}  // namespace pointgen
