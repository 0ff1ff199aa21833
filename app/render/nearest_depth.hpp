#pragma once
#include "app/gl/gl_objects.hpp"

namespace ecoview {

// The nearest surface a frame shows, for the PSM's near plane (seed 000, Sect. 6): the frame's
// linear depth reduced on the GPU to the nearest of each block of pixels, and only those read back.
class NearestDepth {
 public:
  NearestDepth(int width, int height);
  // The nearest positive depth in `depth` (GL_R32F, width × height, negative or 0 where nothing
  // was drawn), in metres; 0 when nothing was drawn.
  float read(GLuint depth) const;

 private:
  int width_, height_;
  gl::Texture blocks_{GL_TEXTURE_2D};
  gl::Framebuffer framebuffer_;
  gl::Program program_;
  gl::VertexArray empty_vertex_array_;  // for the fullscreen triangle, which has no attributes
};

}  // namespace ecoview
