#version 450 core
// `value` where the stencil test let the pixel through: 1 where no shadow volume holds its surface,
// or 0 where one does.
layout(location = 0) out float lit;
uniform float value;

void main() { lit = value; }
