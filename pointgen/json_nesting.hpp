#pragma once
#include <cstddef>
#include <optional>
#include <string_view>

namespace pointgen {

// Recursive JSON readers take a stack frame per level of nesting: tinygltf's, turning extensions
// and extras into Values, overflows the stack on a value nested 100,000 levels deep. So every JSON
// input (scene files, camera paths, glTF, the JSON chunk of .glb) is refused beyond this depth
// before any parser sees it; real files nest a dozen levels.
constexpr int max_json_nesting = 256;

// The byte offset of the first [ or { outside strings that opens a level deeper than
// max_json_nesting, or nothing. A scan with no recursion: it need not be valid JSON.
std::optional<std::size_t> json_nests_too_deep(std::string_view text);

}  // namespace pointgen
