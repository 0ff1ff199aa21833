#version 450 core
// A shadow volume's faces only count in the stencil: no colour, and nothing is discarded.
void main() {}
