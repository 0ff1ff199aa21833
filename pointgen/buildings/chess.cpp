#include "pointgen/buildings/buildings.hpp"
#include "pointgen/mesh_builder.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace pointgen {

TriangleMesh build_chess_board(float square, const glm::vec3& light, const glm::vec3& dark, const glm::vec3& frame) {
  MeshBuilder b;
  const float half = 4.0f * square, thickness = 0.15f * square;
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j) {
      const glm::vec3 c(-half + (static_cast<float>(i) + 0.5f) * square, 0.0f, -half + (static_cast<float>(j) + 0.5f) * square);
      const float y = thickness;
      b.polygon({c + glm::vec3(-0.5f * square, y, 0.5f * square), c + glm::vec3(0.5f * square, y, 0.5f * square),
                 c + glm::vec3(0.5f * square, y, -0.5f * square), c + glm::vec3(-0.5f * square, y, -0.5f * square)},
                (i + j) % 2 == 0 ? dark : light);
    }
  }
  const float rim = 0.5f * square;
  b.box(glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 0.5f * thickness - 0.001f, 0.0f}),
                   {2.0f * (half + rim), thickness, 2.0f * (half + rim)}), frame);
  return b.build();
}

TriangleMesh build_chess_piece(ChessPiece piece, float square) {
  // Profiles (radius, height) in units of a square, bottom to top, closed at both ends.
  std::vector<glm::vec2> p;
  switch (piece) {
    case ChessPiece::pawn:
      p = {{0, 0}, {0.32f, 0}, {0.32f, 0.08f}, {0.22f, 0.14f}, {0.12f, 0.45f}, {0.2f, 0.5f}, {0.1f, 0.55f},
           {0.17f, 0.62f}, {0.19f, 0.72f}, {0.15f, 0.82f}, {0.07f, 0.88f}, {0, 0.9f}};
      break;
    case ChessPiece::rook:
      p = {{0, 0}, {0.35f, 0}, {0.35f, 0.1f}, {0.25f, 0.18f}, {0.2f, 0.75f}, {0.28f, 0.8f}, {0.28f, 1.02f},
           {0.2f, 1.02f}, {0.2f, 0.95f}, {0, 0.95f}};
      break;
    case ChessPiece::knight:
      p = {{0, 0}, {0.35f, 0}, {0.35f, 0.1f}, {0.24f, 0.18f}, {0.16f, 0.55f}, {0.24f, 0.62f}, {0, 0.62f}};
      break;
    case ChessPiece::bishop:
      p = {{0, 0}, {0.34f, 0}, {0.34f, 0.1f}, {0.23f, 0.18f}, {0.13f, 0.7f}, {0.22f, 0.76f}, {0.12f, 0.8f},
           {0.18f, 0.95f}, {0.14f, 1.1f}, {0.06f, 1.18f}, {0.07f, 1.22f}, {0, 1.25f}};
      break;
    case ChessPiece::queen:
      p = {{0, 0}, {0.37f, 0}, {0.37f, 0.1f}, {0.25f, 0.2f}, {0.14f, 0.85f}, {0.25f, 0.92f}, {0.14f, 0.97f},
           {0.24f, 1.22f}, {0.17f, 1.3f}, {0.08f, 1.34f}, {0.07f, 1.4f}, {0, 1.42f}};
      break;
    case ChessPiece::king:
      p = {{0, 0}, {0.38f, 0}, {0.38f, 0.1f}, {0.26f, 0.2f}, {0.15f, 0.95f}, {0.26f, 1.02f}, {0.15f, 1.07f},
           {0.22f, 1.3f}, {0.16f, 1.36f}, {0, 1.36f}};
      break;
  }
  for (glm::vec2& v : p) v *= square;
  MeshBuilder b;
  const glm::vec3 white(1.0f);
  b.lathe(p, 24, white);
  if (piece == ChessPiece::knight) {  // a horse's head: a leaning neck and a muzzle
    const glm::mat4 neck = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.85f, -0.02f) * square),
                                       glm::radians(-15.0f), {1, 0, 0});
    b.box(neck * glm::scale(glm::mat4(1.0f), glm::vec3(0.22f, 0.55f, 0.32f) * square), white);
    b.box(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.02f, 0.18f) * square) *
              glm::rotate(glm::mat4(1.0f), glm::radians(25.0f), {1, 0, 0}) * glm::scale(glm::mat4(1.0f), glm::vec3(0.2f, 0.2f, 0.42f) * square),
          white);
  }
  if (piece == ChessPiece::king) {  // the cross
    b.box(glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.5f, 0.0f) * square), glm::vec3(0.07f, 0.28f, 0.07f) * square), white);
    b.box(glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.53f, 0.0f) * square), glm::vec3(0.2f, 0.07f, 0.07f) * square), white);
  }
  return b.build();
}

}  // namespace pointgen
