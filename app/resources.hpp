#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// Files compiled into the binary at build time: everything under shaders/ and data/, by their path
// from the source root ("shaders/shade.comp", "data/scenes/courtyard.json").
namespace ecoview::resources {

std::optional<std::string_view> find(std::string_view path);
// The stem of every embedded file under `folder` with extension `ext`, e.g. the shipped scenes.
std::vector<std::string> names_in(std::string_view folder, std::string_view ext);

}  // namespace ecoview::resources
