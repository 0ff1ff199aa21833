#version 450 core
// Writes the nearest point depth per texel into a shadow map layer.
layout(std430, binding = 6) readonly buffer Depths { uint depths[]; };
uniform ivec2 target_size;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  uint depth = depths[texel.y * target_size.x + texel.x];
  if (depth == 0xFFFFFFFFu) discard;
  gl_FragDepth = uintBitsToFloat(depth);
}
