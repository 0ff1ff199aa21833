#pragma once
#include "app/gl/gl_objects.hpp"

#include <glm/glm.hpp>

#include <vector>
#include <string>

namespace ecoview::gl {

// Compiles and links the embedded shaders at shaders/<file>, each for the stage its extension
// names: .vert, .tesc, .tese, .geom, .frag, or .comp alone. `defines` (lines of `#define NAME
// VALUE`) go into each file after its `#version` line.
Program build_program(const std::vector<std::string>& files, const std::string& defines = {});
// The define of the programs that draw polygons with textures and alpha masks
// (shaders/surface_texture.glsl): empty when the scene has none.
std::string surface_defines(bool surface_textures);

// Uniform setters by name; a name the linker dropped is ignored, as GL does.
void set_uniform(const Program& program, const char* name, const glm::mat4& value);
void set_uniform(const Program& program, const char* name, const glm::vec4& value);
void set_uniform(const Program& program, const char* name, const glm::vec3& value);
void set_uniform(const Program& program, const char* name, float value);
void set_uniform(const Program& program, const char* name, int value);
void set_uniform(const Program& program, const char* name, unsigned value);
void set_uniform(const Program& program, const char* name, const glm::vec2& value);
void set_uniform(const Program& program, const char* name, const glm::ivec2& value);

}  // namespace ecoview::gl
