#version 450 core
// Depth only: the depth test writes the map.
void main() {}
