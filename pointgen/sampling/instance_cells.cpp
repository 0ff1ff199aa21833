#include "pointgen/sampling/instance_cells.hpp"

#include "pointgen/random.hpp"
#include "pointgen/sampling/view_sampler.hpp"

#include <algorithm>
#include <span>
#include <tuple>

namespace pointgen {
namespace {

struct Placed {
  std::uint32_t instance = 0;
  glm::vec3 center{0.0f};
  float radius = 0.0f, area = 0.0f;
};

InstanceCell cell_of(std::span<Placed> placed, std::uint32_t table, const InstanceTable& instances) {
  InstanceCell cell;
  cell.table = table;
  cell.min = glm::vec3(INFINITY);
  cell.max = glm::vec3(-INFINITY);
  for (const Placed& p : placed) {
    cell.members.push_back(p.instance);
    cell.min = glm::min(cell.min, p.center - p.radius);
    cell.max = glm::max(cell.max, p.center + p.radius);
    cell.area += p.area;
  }
  // Shuffled by the first member's seed: the same cells in every process.
  const std::uint32_t first = cell.members.front();
  Random random(derive_seed(instances.seeds.size() > first ? instances.seeds[first] : first, 0x63656c6cu));
  for (std::size_t i = cell.members.size(); i > 1; --i) {
    std::swap(cell.members[i - 1], cell.members[random.below(static_cast<std::uint32_t>(i))]);
  }
  return cell;
}

void split(std::span<Placed> placed, std::uint32_t table, const InstanceTable& instances, std::vector<InstanceCell>& cells) {
  if (placed.size() <= InstanceCells::max_members) {
    cells.push_back(cell_of(placed, table, instances));
    return;
  }
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const Placed& p : placed) {
    lo = glm::min(lo, p.center);
    hi = glm::max(hi, p.center);
  }
  const int axis = hi.x - lo.x >= hi.z - lo.z ? 0 : 2;
  const auto middle = placed.begin() + static_cast<std::ptrdiff_t>(placed.size() / 2);
  std::nth_element(placed.begin(), middle, placed.end(), [axis](const Placed& a, const Placed& b) {
    return std::tie(a.center[axis], a.instance) < std::tie(b.center[axis], b.instance);
  });
  split(placed.first(placed.size() / 2), table, instances, cells);
  split(placed.subspan(placed.size() / 2), table, instances, cells);
}

}  // namespace

InstanceCells::InstanceCells(const TableList& tables, const std::vector<SampledMesh>& meshes)
    : by_table_(tables.size()) {
  for (std::size_t t = 0; t < tables.size(); ++t) update(t, tables[t], meshes[tables[t].mesh]);
}

void InstanceCells::update(std::size_t table, const InstanceTable& instances, const SampledMesh& mesh) {
  std::vector<Placed> placed;
  placed.reserve(instances.size());
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const glm::mat4 m = instances.transform(i);
    const float scale = uniform_scale(m);
    placed.push_back({static_cast<std::uint32_t>(i), glm::vec3(m * glm::vec4(mesh.center, 1.0f)), mesh.radius * scale,
                      mesh.area * scale * scale});
  }
  std::vector<InstanceCell>& cells = by_table_[table];
  cells.clear();
  if (!placed.empty()) split(placed, static_cast<std::uint32_t>(table), instances, cells);
}

}  // namespace pointgen
