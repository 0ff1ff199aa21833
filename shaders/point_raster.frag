#version 450 core
// The colour of a rasterized point sample (point_raster.vert).
in vec3 point_color;
out vec4 color;

void main() { color = vec4(point_color, 1.0); }
