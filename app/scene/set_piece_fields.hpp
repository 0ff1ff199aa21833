#pragma once
#include "app/scene/json_input.hpp"
#include "pointgen/triangle_mesh.hpp"

#include <functional>
#include <vector>

// Readers for built set pieces: cathedral, house rows, chess set, lathe-turned objects.
namespace ecoview {

// A mesh and where its instances stand, with their colours (linear RGB).
struct PlacedMesh {
  pointgen::TriangleMesh mesh;
  std::vector<glm::mat4> transforms;
  std::vector<glm::vec3> colors;
};

// Counts bytes a set piece will take against the scene's memory budget (InputError on the field
// when over it).
using ReserveMemory = std::function<void(const JsonField& field, double bytes)>;

// Reads an object of one of these types; returns nothing for other types.
// {"type": "cathedral", "center", "yaw_deg", "length", "width", "height", "color", "roof_color"}
// {"type": "houses", "from": [x, z], "to": [x, z], "front": "left" | "right", "depth", "seed"}
// {"type": "chess", "center", "square"}: a board with the 32 pieces in their starting places
// {"type": "lathe", "profile": [[radius, height], ...], "center", "sides", "color"}
std::vector<PlacedMesh> read_set_piece(const JsonField& field, const std::string& type, std::uint64_t scene_seed,
                                       const ReserveMemory& reserve_memory);

}  // namespace ecoview
