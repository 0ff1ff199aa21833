#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <cstdint>
#include <vector>

// Buildings and set pieces as polygons: they are big and flat, where polygons are cheaper than
// points.
namespace pointgen {

// A cathedral-like church standing on the origin, its portal facing +Z: a nave with a pitched
// roof, two west towers with spires, buttresses along the sides, a portal and an apse. Sizes are
// metres; colours linear RGB.
struct CathedralSpec {
  float length = 60.0f;
  float width = 22.0f;
  float height = 28.0f;  // of the nave walls; towers and spires rise above
  glm::vec3 stone{0.55f, 0.50f, 0.42f};
  glm::vec3 roof{0.18f, 0.20f, 0.22f};
};
TriangleMesh build_cathedral(const CathedralSpec& spec);

// A row of town houses along the segment from `from` to `to` (on the ground), their fronts
// facing `front` side (+1: left of the direction of travel, -1: right), `depth` deep.
TriangleMesh build_house_row(const glm::vec2& from, const glm::vec2& to, int front, float depth, std::uint64_t seed);

// A chess board of 8 x 8 squares of `square` metres centred on the origin, with a frame.
TriangleMesh build_chess_board(float square, const glm::vec3& light, const glm::vec3& dark, const glm::vec3& frame);

enum class ChessPiece { pawn, rook, knight, bishop, queen, king };
// A turned piece (surface of revolution; the knight with a head on top) one `square` wide.
TriangleMesh build_chess_piece(ChessPiece piece, float square);

}  // namespace pointgen
