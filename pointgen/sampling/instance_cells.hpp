#pragma once
#include "pointgen/table_list.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace pointgen {

struct SampledMesh;

// A few instances of one table that stand together: the sampler culls, orders and hides them as
// one before it looks at any of them, and counts far ones as one (docs/point_density.md, "Cells").
struct InstanceCell {
  std::uint32_t table = 0;
  // Instance indices in a fixed random order, so that the first n of them are a random choice.
  std::vector<std::uint32_t> members;
  glm::vec3 min{0.0f}, max{0.0f};  // a box around the members' bounding spheres
  float area = 0.0f;               // the members' surface, square metres
};

// Every table's instances in cells of at most `max_members`: split in two at the median along the
// longer horizontal side of their centres' bounds, and again, so cells follow how instances
// cluster (groves, patches) and hold about as many each.
class InstanceCells {
 public:
  static constexpr std::size_t max_members = 64;

  InstanceCells(const TableList& tables, const std::vector<SampledMesh>& meshes);
  // Makes the cells of one table again, after its instances moved.
  void update(std::size_t table, const InstanceTable& instances, const SampledMesh& mesh);
  // Per table, its cells.
  const std::vector<std::vector<InstanceCell>>& by_table() const { return by_table_; }

 private:
  std::vector<std::vector<InstanceCell>> by_table_;
};

}  // namespace pointgen
