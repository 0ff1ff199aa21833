#version 450 core
// Between the GPU sampler's histogram and its keys, one thread: the frame's distance bands, as
// many as the ladder's (GpuSampler::bands). A band of the ladder that holds more than dense_plants
// plants in view is cut at its quarters into bands of about that many (the plants of one band do
// not hide each other, and a dense stand's band holds thousands of trees), nearest first; the
// bands the cuts take are those farthest, merged into the last, which reaches to infinity. Without
// a dense band they are the ladder's. The quarters' counts are cleared for the next frame.
layout(local_size_x = 1) in;

layout(std430, binding = 34) buffer BandEnds {
  float band_ends[32];
  uint quarter_counts[];
};
uniform float ladder_ends[32];  // the last's infinite
uniform uint ladder_count;
uniform uint dense_plants;

void main() {
  uint band = 0u;
  // The ladder's finite bands, nearest first, while a band is left for the rest.
  for (uint k = 0u; k + 1u < ladder_count && band + 1u < ladder_count; ++k) {
    float start = k > 0u ? ladder_ends[k - 1u] : 0.0;
    uint plants = 0u;  // in the band being filled
    for (uint q = 0u; q < 4u; ++q) {
      uint here = quarter_counts[4u * k + q];
      // A cut takes a band: this one's end and the last must still fit.
      if (q > 0u && plants > 0u && plants + here > dense_plants && band + 2u < ladder_count) {
        band_ends[band++] = start + (ladder_ends[k] - start) * 0.25 * float(q);
        plants = 0u;
      }
      plants += here;
    }
    band_ends[band++] = ladder_ends[k];
  }
  band_ends[band++] = ladder_ends[ladder_count - 1u];
  for (uint q = 0u; q < 4u * ladder_count; ++q) quarter_counts[q] = 0u;
}
