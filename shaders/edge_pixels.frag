#version 450 core
// Keeps the pixels whose shadow-map test was neither lit nor shadowed: some of the filtered taps
// disagreed, so an edge of the map's shadow passes near (Chan and Durand 2004). The stencil marks
// them; the others are discarded.
layout(binding = 0) uniform sampler2D visibility;  // the frame's `shadow` AOV, lit by the map

void main() {
  float v = texelFetch(visibility, ivec2(gl_FragCoord.xy), 0).r;
  if (v == 0.0 || v == 1.0) discard;
}
