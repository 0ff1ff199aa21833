#include "pointgen/triangle_adjacency.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace pointgen {
namespace {

using Position = std::array<float, 3>;

Position key(const glm::vec3& p) { return {p.x, p.y, p.z}; }

// One side of an edge: the positions of its ends in order, the triangle and the vertex across.
struct HalfEdge {
  Position from, to;
  std::uint32_t across = 0;
  std::size_t slot = 0;  // where its neighbour's vertex goes in the adjacency indices
};

// The edge without its direction: its two ends in order of position.
std::pair<Position, Position> undirected(const HalfEdge& e) { return std::minmax(e.from, e.to); }

}  // namespace

std::vector<std::uint32_t> adjacency_indices(const TriangleMesh& mesh) {
  const std::size_t triangles = mesh.triangle_count();
  std::vector<std::uint32_t> out(6 * triangles);
  std::vector<HalfEdge> edges;
  edges.reserve(3 * triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.indices[3 * t + i], b = mesh.indices[3 * t + (i + 1) % 3],
                          c = mesh.indices[3 * t + (i + 2) % 3];
      out[6 * t + 2 * i] = a;
      out[6 * t + 2 * i + 1] = c;  // no neighbour yet: the triangle's own third vertex
      edges.push_back({key(mesh.positions[a]), key(mesh.positions[b]), c, 6 * t + 2 * i + 1});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) { return undirected(x) < undirected(y); });
  for (std::size_t first = 0; first < edges.size();) {
    std::size_t end = first + 1;
    while (end < edges.size() && undirected(edges[end]) == undirected(edges[first])) ++end;
    if (end - first == 2) {  // exactly two triangles share it
      out[edges[first].slot] = edges[first + 1].across;
      out[edges[first + 1].slot] = edges[first].across;
    }
    first = end;
  }
  return out;
}

}  // namespace pointgen
