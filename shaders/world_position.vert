#version 450 core
// World positions for the stages after this one to project (shadow volumes, paraboloid maps).
layout(location = 0) in vec3 position;
#include "instance.glsl"

out vec3 world_position;
#ifdef SURFACE_TEXTURES
layout(location = 11) in vec4 surface;
out vec4 vertex_surface;
#endif

void main() {
  world_position = (instance_model() * vec4(position, 1.0)).xyz;
#ifdef SURFACE_TEXTURES
  vertex_surface = surface;
#endif
}
