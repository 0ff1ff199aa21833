#version 450 core
// Depth only: the depth test writes the target (a shadow map, the frame's depth pre-pass).
void main() {}
