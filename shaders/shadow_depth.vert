#version 450 core
// Depth of the scene as the light sees it.
layout(location = 0) in vec3 position;
#include "instance.glsl"

uniform mat4 light_view_projection;

void main() {
  gl_Position = light_view_projection * (instance_model() * vec4(position, 1.0));
}
