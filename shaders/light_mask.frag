#version 450 core
// 1 where the stencil test let the pixel through: no shadow volume holds its surface.
layout(location = 0) out float lit;

void main() { lit = 1.0; }
