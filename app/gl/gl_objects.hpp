#pragma once
#include <glad/gl.h>

#include <algorithm>
#include <utility>
#include <vector>

// Owners of GL object names: created in the constructor, deleted in the destructor, movable,
// not copyable. They need a current context with the GL functions loaded.
namespace ecoview::gl {

template <class Kind>
class Object {
 public:
  template <class... Args>
  explicit Object(Args... args) : name_(Kind::create(args...)) {}
  ~Object() {
    if (name_ != 0) Kind::destroy(name_);
  }
  Object(Object&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  Object& operator=(Object&& other) noexcept {
    std::swap(name_, other.name_);
    return *this;
  }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;

  GLuint name() const { return name_; }

 private:
  GLuint name_;
};

struct BufferKind {
  static GLuint create() { GLuint n = 0; glCreateBuffers(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct VertexArrayKind {
  static GLuint create() { GLuint n = 0; glCreateVertexArrays(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct TextureKind {
  static GLuint create(GLenum target) { GLuint n = 0; glCreateTextures(target, 1, &n); return n; }
  static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
// A texture name never bound, which glTextureView needs.
struct TextureViewKind {
  static GLuint create() { GLuint n = 0; glGenTextures(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct FramebufferKind {
  static GLuint create() { GLuint n = 0; glCreateFramebuffers(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct ProgramKind {
  static GLuint create() { return glCreateProgram(); }
  static void destroy(GLuint n) { glDeleteProgram(n); }
};
struct ShaderKind {
  static GLuint create(GLenum type) { return glCreateShader(type); }
  static void destroy(GLuint n) { glDeleteShader(n); }
};

struct QueryKind {
  static GLuint create(GLenum target) { GLuint n = 0; glCreateQueries(target, 1, &n); return n; }
  static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};

using Buffer = Object<BufferKind>;

// Immutable storage for `buffer` holding `data`; an empty vector still gets a few bytes, as GL
// refuses storage of size 0.
template <class T>
void store(const Buffer& buffer, const std::vector<T>& data, GLbitfield flags = 0) {
  glNamedBufferStorage(buffer.name(), static_cast<GLsizeiptr>(std::max<std::size_t>(data.size(), 1) * sizeof(T)),
                       data.empty() ? nullptr : data.data(), flags);
}

// The bytes of one storage buffer a shader can address on this driver (GL promises 2^27).
inline std::size_t max_storage_block_bytes() {
  GLint64 bytes = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
  return static_cast<std::size_t>(bytes);
}

// The texels of one buffer texture this driver holds (GL promises 2^16; llvmpipe 2^27).
inline std::size_t max_texel_buffer_texels() {
  GLint64 texels = 0;
  glGetInteger64v(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
  return static_cast<std::size_t>(texels);
}

using VertexArray = Object<VertexArrayKind>;
using Texture = Object<TextureKind>;
using TextureView = Object<TextureViewKind>;
using Framebuffer = Object<FramebufferKind>;
using Program = Object<ProgramKind>;
using Shader = Object<ShaderKind>;
using Query = Object<QueryKind>;

// Binds `framebuffer` for drawing over its whole width x height with the depth test (the nearer
// wins) and both faces of every triangle: planes are single-sided, but seen and cast from both.
inline void draw_depth_tested(const Framebuffer& framebuffer, int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.name());
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
}

// `buffer`'s content as texels of `format`, for shaders that read it by texelFetch (a buffer texture
// over its store). Made once a store: attaching it again at every bind slowed llvmpipe's draws.
inline Texture buffer_texels(const Buffer& buffer, GLenum format = GL_RGBA32F) {
  Texture texels(GL_TEXTURE_BUFFER);
  glTextureBuffer(texels.name(), format, buffer.name());
  return texels;
}

}  // namespace ecoview::gl
