#version 450 core
// The points' nearest depths (point_depth.comp; the far plane where none) drawn into a shadow
// map's layer over a full-screen triangle with the depth test LESS: a texel changes where a point
// lies nearer than the polygons. A draw, not a pixel upload from the buffer: on an
// NVIDIA H200 that upload of a 2048² layer took 9 ms, as long as its points.
layout(std430, binding = 6) readonly buffer Depths { float depths[]; };  // rows from the bottom
uniform int width;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  gl_FragDepth = depths[texel.y * width + texel.x];
}
