#version 450 core
// The nearest drawn depth in one block of the frame's linear view depth; 1e30 where none was drawn.
layout(binding = 0) uniform sampler2D depth;
uniform int block;
layout(location = 0) out float nearest;

void main() {
  ivec2 size = textureSize(depth, 0);
  ivec2 first = ivec2(gl_FragCoord.xy) * block;
  ivec2 last = min(first + block, size);
  nearest = 1e30;
  for (int y = first.y; y < last.y; ++y) {
    for (int x = first.x; x < last.x; ++x) {
      float d = texelFetch(depth, ivec2(x, y), 0).r;
      if (d > 0.0) nearest = min(nearest, d);
    }
  }
}
