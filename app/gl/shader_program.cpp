#include "app/gl/shader_program.hpp"

#include "app/errors.hpp"
#include "app/resources.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <sstream>

namespace ecoview::gl {
namespace {

// The embedded source of shaders/<file> with each line `#include "other"` replaced by that file.
std::string source_of(const std::string& file, int depth = 0) {
  const auto text = resources::find("shaders/" + file);
  if (depth > 8) throw RuntimeFailure("shader shaders/" + file + ": includes nest deeper than 8");
  if (!text) throw RuntimeFailure("shader shaders/" + file + " is not embedded in this binary");
  std::istringstream lines{std::string(*text)};
  std::string out, line;
  while (std::getline(lines, line)) {
    const std::size_t open = line.rfind("#include \"", 0) == 0 ? line.find('"') : std::string::npos;
    const std::size_t close = open == std::string::npos ? open : line.find('"', open + 1);
    out += close == std::string::npos ? line + "\n" : source_of(line.substr(open + 1, close - open - 1), depth + 1);
  }
  return out;
}

// The source with `defines` after its first line, which is its `#version`.
std::string with_defines(const std::string& source, const std::string& defines) {
  const std::size_t line_end = source.find('\n');
  if (defines.empty() || line_end == std::string::npos) return source;
  return source.substr(0, line_end + 1) + defines + source.substr(line_end + 1);
}

Shader compile(GLenum type, const std::string& file, const std::string& defines) {
  const std::string source = with_defines(source_of(file), defines);
  Shader shader(type);
  const char* text = source.data();
  const auto length = static_cast<GLint>(source.size());
  glShaderSource(shader.name(), 1, &text, &length);
  glCompileShader(shader.name());
  GLint ok = 0;
  glGetShaderiv(shader.name(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader.name(), sizeof log, nullptr, log);
    throw RuntimeFailure("shaders/" + file + " does not compile on this driver: " + log);
  }
  return shader;
}

// The stage of a shader file, by its extension.
GLenum stage_of(const std::string& file) {
  const std::string extension = file.substr(file.rfind('.') + 1);
  if (extension == "vert") return GL_VERTEX_SHADER;
  if (extension == "tesc") return GL_TESS_CONTROL_SHADER;
  if (extension == "tese") return GL_TESS_EVALUATION_SHADER;
  if (extension == "geom") return GL_GEOMETRY_SHADER;
  if (extension == "frag") return GL_FRAGMENT_SHADER;
  if (extension == "comp") return GL_COMPUTE_SHADER;
  throw RuntimeFailure("shaders/" + file + ": no shader stage has the extension ." + extension);
}

}  // namespace

std::string surface_defines(bool surface_textures) { return surface_textures ? "#define SURFACE_TEXTURES\n" : ""; }

Program build_program(const std::vector<std::string>& files, const std::string& defines) {
  std::vector<Shader> shaders;
  std::string names;
  for (const std::string& file : files) {
    shaders.push_back(compile(stage_of(file), file, defines));
    names += (names.empty() ? "" : " + ") + file;
  }
  Program program;
  for (const Shader& shader : shaders) glAttachShader(program.name(), shader.name());
  glLinkProgram(program.name());
  GLint ok = 0;
  glGetProgramiv(program.name(), GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(program.name(), sizeof log, nullptr, log);
    throw RuntimeFailure("shaders " + names + " do not link: " + log);
  }
  for (const Shader& shader : shaders) glDetachShader(program.name(), shader.name());
  return program;
}

void set_uniform(const Program& program, const char* name, const glm::mat4& value) {
  glProgramUniformMatrix4fv(program.name(), glGetUniformLocation(program.name(), name), 1, GL_FALSE,
                            glm::value_ptr(value));
}
void set_uniform(const Program& program, const char* name, const glm::vec4& value) {
  glProgramUniform4fv(program.name(), glGetUniformLocation(program.name(), name), 1, glm::value_ptr(value));
}

void set_uniform(const Program& program, const char* name, const glm::vec3& value) {
  glProgramUniform3fv(program.name(), glGetUniformLocation(program.name(), name), 1, glm::value_ptr(value));
}
void set_uniform(const Program& program, const char* name, float value) {
  glProgramUniform1f(program.name(), glGetUniformLocation(program.name(), name), value);
}
void set_uniform(const Program& program, const char* name, int value) {
  glProgramUniform1i(program.name(), glGetUniformLocation(program.name(), name), value);
}
void set_uniform(const Program& program, const char* name, unsigned value) {
  glProgramUniform1ui(program.name(), glGetUniformLocation(program.name(), name), value);
}
void set_uniform(const Program& program, const char* name, const glm::vec2& value) {
  glProgramUniform2f(program.name(), glGetUniformLocation(program.name(), name), value.x, value.y);
}

void set_uniform(const Program& program, const char* name, const glm::ivec2& value) {
  glProgramUniform2i(program.name(), glGetUniformLocation(program.name(), name), value.x, value.y);
}

}  // namespace ecoview::gl
