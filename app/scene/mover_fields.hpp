#pragma once
#include "app/scene/json_input.hpp"
#include "pointgen/movers/moving_set.hpp"

// Readers for the moving parts of a scene file: crowds and traffic.
namespace ecoview {

// {"type": "crowd", "count", "center": [x, y, z], "size": [w, d], "avoid": [[x0, z0, x1, z1], ...], "seed"}
pointgen::MovingSet read_crowd(const JsonField& field, std::uint64_t scene_seed);

// {"type": "traffic", "seed", "y", "cars", "loops": [[x0, z0, x1, z1], ...], "aeroplanes", "center", "radius",
//  "altitude"}
pointgen::MovingSet read_traffic(const JsonField& field, std::uint64_t scene_seed);

// A rectangle [x0, z0, x1, z1] with x0 < x1 and z0 < z1.
pointgen::Rect read_rect(const JsonField& field);

}  // namespace ecoview
