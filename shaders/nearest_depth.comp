#version 450 core
// The nearest surface of the frame: the least positive linear view depth of its depth target, as
// float bits (positive floats order like their bits), by a work group's own minimum and then one
// atomicMin a group. `nearest` starts at all ones: none.
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = 26) buffer Nearest { uint nearest; };
uniform sampler2D view_depth;  // negative where no surface was drawn

shared uint group_nearest[256];

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  uint own = 0xFFFFFFFFu;
  if (all(lessThan(pixel, textureSize(view_depth, 0)))) {
    float d = texelFetch(view_depth, pixel, 0).r;
    if (d > 0.0) own = floatBitsToUint(d);
  }
  uint t = gl_LocalInvocationIndex;
  group_nearest[t] = own;
  barrier();
  for (uint half_count = 128u; half_count > 0u; half_count /= 2u) {
    if (t < half_count) group_nearest[t] = min(group_nearest[t], group_nearest[t + half_count]);
    barrier();
  }
  if (t == 0u && group_nearest[0] != 0xFFFFFFFFu) atomicMin(nearest, group_nearest[0]);
}
