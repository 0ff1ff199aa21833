#version 450 core
// World positions for the stages after this one to project (shadow volumes, paraboloid maps).
layout(location = 0) in vec3 position;
#include "instance.glsl"

out vec3 world_position;

void main() { world_position = (instance_model() * vec4(position, 1.0)).xyz; }
