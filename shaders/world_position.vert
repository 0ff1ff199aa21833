#version 450 core
// World positions for the stages after this one to project (shadow volumes, paraboloid maps).
layout(location = 0) in vec3 position;
layout(location = 3) in mat4 model;

out vec3 world_position;

void main() { world_position = (model * vec4(position, 1.0)).xyz; }
