#pragma once
#include "pointgen/instance_table.hpp"
#include "pointgen/sampling/instance_cells.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace pointgen {

struct SampledMesh;

// The frusta of one or more world → clip matrices: a sphere is in view when it reaches into any.
class ViewFrusta {
 public:
  explicit ViewFrusta(const std::vector<glm::mat4>& views);
  bool hold(const glm::vec3& center, float radius) const;
  const std::vector<std::array<glm::vec4, 6>>& planes() const { return planes_; }

 private:
  std::vector<std::array<glm::vec4, 6>> planes_;  // per view, inside where dot >= 0
};

// The instances of one table whose bounding spheres are in view, found cell by cell (a cell out of
// view is skipped whole), in the table's order.
std::vector<std::uint32_t> instances_in_view(const ViewFrusta& frusta, const std::vector<InstanceCell>& cells,
                                             const InstanceTable& table, const SampledMesh& mesh);

}  // namespace pointgen
