#version 450 core
// The nearest surface of the frame: the least positive linear view depth of its depth target, as
// float bits (positive floats order like their bits). Each thread takes the minimum over a block
// of 8 × 8 pixels and makes one atomicMin: no work-group reduction, whose barriers cost llvmpipe
// more than the reads. `nearest` starts at all ones: none.
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 26) buffer Nearest { uint nearest; };
uniform sampler2D view_depth;  // negative where no surface was drawn

const int block = 8;

void main() {
  ivec2 origin = ivec2(gl_GlobalInvocationID.xy) * block;
  ivec2 end = min(origin + block, textureSize(view_depth, 0));
  uint own = 0xFFFFFFFFu;
  for (int y = origin.y; y < end.y; ++y) {
    for (int x = origin.x; x < end.x; ++x) {
      float d = texelFetch(view_depth, ivec2(x, y), 0).r;
      if (d > 0.0) own = min(own, floatBitsToUint(d));
    }
  }
  if (own != 0xFFFFFFFFu) atomicMin(nearest, own);
}
