#version 450 core
layout(triangles, equal_spacing, ccw) in;

in vec3 patch_position[];

uniform mat4 light_view;
uniform vec2 paraboloid;  // zoom, range

#include "paraboloid.glsl"

void main() {
  vec3 p = gl_TessCoord.x * patch_position[0] + gl_TessCoord.y * patch_position[1] + gl_TessCoord.z * patch_position[2];
  gl_Position = paraboloid_clip(light_view, paraboloid, p);
}
