#include "app/scene/set_piece_fields.hpp"

#include "app/scene/scene_fields.hpp"
#include "pointgen/buildings/buildings.hpp"
#include "pointgen/mesh_builder.hpp"
#include "pointgen/random.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace ecoview {
namespace {

glm::mat4 at(const glm::vec3& center, float yaw_deg = 0.0f) {
  return glm::rotate(glm::translate(glm::mat4(1.0f), center), glm::radians(yaw_deg), glm::vec3(0, 1, 0));
}

glm::vec3 color_or(const JsonField& field, const char* key, const glm::vec3& fallback) {
  return field.has(key) ? srgb_to_linear(field[key].color()) : fallback;
}

std::vector<PlacedMesh> cathedral(const JsonField& field) {
  field.only_keys({"type", "center", "yaw_deg", "length", "width", "height", "color", "roof_color"});
  pointgen::CathedralSpec spec;
  if (auto f = field.optional("length")) spec.length = f->number_f(5, 1000);
  if (auto f = field.optional("width")) spec.width = f->number_f(3, 500);
  if (auto f = field.optional("height")) spec.height = f->number_f(3, 500);
  spec.stone = color_or(field, "color", spec.stone);
  spec.roof = color_or(field, "roof_color", spec.roof);
  const float yaw = field.has("yaw_deg") ? field["yaw_deg"].number_f(-360, 360) : 0.0f;
  return {{pointgen::build_cathedral(spec), {at(field["center"].vec3(), yaw)}, {glm::vec3(1.0f)}}};
}

// A house row's mesh and its copy for the GPU, per metre of row: 18.6 triangles a metre, and the
// resident memory `capture` reports on its scene line grew from 63 to 117 MiB from a 1 km to a
// 10 km row (6.3 kB a metre).
constexpr double house_row_bytes_per_metre = 6500.0;

std::vector<PlacedMesh> houses(const JsonField& field, std::uint64_t scene_seed, const ReserveMemory& reserve_memory) {
  field.only_keys({"type", "from", "to", "front", "depth", "seed"});
  const std::vector<double> from = field["from"].numbers(2, -JsonField::max_coordinate, JsonField::max_coordinate);
  const std::vector<double> to = field["to"].numbers(2, -JsonField::max_coordinate, JsonField::max_coordinate);
  if (from == to) field["to"].fail("must differ from \"from\"");
  reserve_memory(field, house_row_bytes_per_metre * std::hypot(to[0] - from[0], to[1] - from[1]));
  int front = 1;
  if (auto f = field.optional("front")) {
    const std::string side = f->string();
    if (side != "left" && side != "right") f->fail("expected \"left\" or \"right\"");
    front = side == "left" ? 1 : -1;
  }
  const float depth = field.has("depth") ? field["depth"].number_f(2, 200) : 12.0f;
  const auto seed = pointgen::derive_seed(scene_seed, field.has("seed") ? static_cast<std::uint64_t>(field["seed"].integer(0, 2147483647)) : 0u);
  return {{pointgen::build_house_row({from[0], from[1]}, {to[0], to[1]}, front, depth, seed), {glm::mat4(1.0f)}, {glm::vec3(1.0f)}}};
}

std::vector<PlacedMesh> chess(const JsonField& field) {
  field.only_keys({"type", "center", "square"});
  const glm::vec3 center = field["center"].vec3();
  const float square = field.has("square") ? field["square"].number_f(0.01, 100) : 1.0f;
  std::vector<PlacedMesh> out;
  out.push_back({pointgen::build_chess_board(square, {0.80f, 0.72f, 0.55f}, {0.20f, 0.11f, 0.05f}, {0.10f, 0.06f, 0.03f}),
                 {at(center)}, {glm::vec3(1.0f)}});
  using P = pointgen::ChessPiece;
  const P back_rank[8] = {P::rook, P::knight, P::bishop, P::queen, P::king, P::bishop, P::knight, P::rook};
  const glm::vec3 white(0.85f, 0.80f, 0.70f), black(0.06f, 0.05f, 0.05f);
  for (P piece : {P::pawn, P::rook, P::knight, P::bishop, P::queen, P::king}) {
    PlacedMesh placed{pointgen::build_chess_piece(piece, square), {}, {}};
    for (int side = 0; side < 2; ++side) {
      for (int file = 0; file < 8; ++file) {
        const int rank = piece == P::pawn ? (side == 0 ? 1 : 6) : (side == 0 ? 0 : 7);
        if (piece != P::pawn && back_rank[file] != piece) continue;
        const glm::vec3 square_center = center + square * glm::vec3(static_cast<float>(file) - 3.5f, 0.15f,
                                                                    3.5f - static_cast<float>(rank));
        placed.transforms.push_back(at(square_center, side == 0 ? 0.0f : 180.0f));
        placed.colors.push_back(side == 0 ? white : black);
      }
    }
    out.push_back(std::move(placed));
  }
  return out;
}

std::vector<PlacedMesh> lathe(const JsonField& field) {
  field.only_keys({"type", "profile", "center", "sides", "color"});
  std::vector<glm::vec2> profile;
  for (const JsonField& item : field["profile"].items(2)) {
    const std::vector<double> p = item.numbers(2, -JsonField::max_coordinate, JsonField::max_coordinate);
    if (p[0] < 0) item.fail("a radius cannot be negative");
    profile.emplace_back(p[0], p[1]);
  }
  const int sides = field.has("sides") ? field["sides"].integer(3, 256) : 48;
  pointgen::MeshBuilder b;
  b.lathe(profile, sides, glm::vec3(1.0f));
  return {{b.build(), {at(field["center"].vec3())}, {color_or(field, "color", glm::vec3(0.6f))}}};
}

}  // namespace

std::vector<PlacedMesh> read_set_piece(const JsonField& field, const std::string& type, std::uint64_t scene_seed,
                                       const ReserveMemory& reserve_memory) {
  if (type == "cathedral") return cathedral(field);
  if (type == "houses") return houses(field, scene_seed, reserve_memory);
  if (type == "chess") return chess(field);
  if (type == "lathe") return lathe(field);
  return {};
}

}  // namespace ecoview
