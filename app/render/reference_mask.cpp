#include "app/render/reference_mask.hpp"

#include <cstdint>
#include <vector>

namespace ecoview {

ReferenceMask::ReferenceMask(const MaskSources& sources) : exact_(sources.exact) {
  glTextureStorage2D(mask_.name(), 1, GL_R8, sources.size.x, sources.size.y);
}

GLuint ReferenceMask::render(const MaskFrame& frame) {
  const Image8 lit = exact_().trace(frame.camera, frame.light, frame.frame.read_depth());
  std::vector<std::uint8_t> bottom_up;  // GL's rows go up from the bottom
  bottom_up.reserve(lit.samples.size());
  for (int y = lit.height - 1; y >= 0; --y) {
    const auto row = lit.samples.begin() + static_cast<std::ptrdiff_t>(y) * lit.width;
    bottom_up.insert(bottom_up.end(), row, row + lit.width);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(mask_.name(), 0, 0, 0, lit.width, lit.height, GL_RED, GL_UNSIGNED_BYTE, bottom_up.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  return mask_.name();
}

}  // namespace ecoview
