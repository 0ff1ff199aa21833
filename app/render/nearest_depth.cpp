#include "app/render/nearest_depth.hpp"

#include "app/gl/shader_program.hpp"

#include <algorithm>
#include <vector>

namespace ecoview {
namespace {

constexpr int block = 8;  // pixels per side of a block: 1/64 of the frame is read back

}  // namespace

NearestDepth::NearestDepth(int width, int height)
    : width_((width + block - 1) / block),
      height_((height + block - 1) / block),
      program_(gl::build_program({"fullscreen.vert", "nearest_depth.frag"})) {
  glTextureStorage2D(blocks_.name(), 1, GL_R32F, width_, height_);
  glNamedFramebufferTexture(framebuffer_.name(), GL_COLOR_ATTACHMENT0, blocks_.name(), 0);
}

float NearestDepth::read(GLuint depth) const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.name());
  glViewport(0, 0, width_, height_);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program_.name());
  gl::set_uniform(program_, "block", block);
  glBindTextureUnit(0, depth);
  glBindVertexArray(empty_vertex_array_.name());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  std::vector<float> nearest(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
  glNamedFramebufferReadBuffer(framebuffer_.name(), GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.name());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_RED, GL_FLOAT, nearest.data());
  const float least = *std::min_element(nearest.begin(), nearest.end());
  return least < 1e29f ? least : 0.0f;
}

}  // namespace ecoview
