#pragma once
#include "app/gl/gl_objects.hpp"

#include <glm/glm.hpp>

#include <string>

namespace ecoview::gl {

// Compiles and links the embedded shaders at shaders/<vertex> and shaders/<fragment>.
Program build_program(const std::string& vertex, const std::string& fragment);
// The same with tessellation control and evaluation stages between them.
Program build_program(const std::string& vertex, const std::string& tess_control, const std::string& tess_evaluation,
                      const std::string& fragment);
// Compiles and links the embedded compute shader at shaders/<compute>.
Program build_compute_program(const std::string& compute);

// Uniform setters by name; a name the linker dropped is ignored, as GL does.
void set_uniform(const Program& program, const char* name, const glm::mat4& value);
void set_uniform(const Program& program, const char* name, const glm::vec3& value);
void set_uniform(const Program& program, const char* name, float value);
void set_uniform(const Program& program, const char* name, int value);
void set_uniform(const Program& program, const char* name, unsigned value);
void set_uniform(const Program& program, const char* name, const glm::vec2& value);
void set_uniform(const Program& program, const char* name, const glm::ivec2& value);

}  // namespace ecoview::gl
