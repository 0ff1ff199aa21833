#version 450 core
// Between the GPU sampler's histogram and its keys, one thread: the frame's distance bands, as
// many as the ladder's (GpuSampler::bands). A band of the ladder whose plants in view weigh more
// than dense_plants (a plant the count will likely draw as polygons weighs more: sample_bins.comp)
// is cut at its quarters into bands of about that weight, nearest first, for the plants of one band
// do not hide each other; each cut takes the place of a ladder band with no plants in view, and the
// places no cut took are empty bands at the end. The quarters' counts are cleared for the next frame.
layout(local_size_x = 1) in;

layout(std430, binding = 34) buffer BandEnds {
  float band_ends[32];
  uint quarter_counts[];
};
uniform float ladder_ends[32];  // the last's infinite
uniform uint ladder_count;
uniform uint dense_plants;

uint ladder_band_weight(uint k) {
  return quarter_counts[4u * k] + quarter_counts[4u * k + 1u] + quarter_counts[4u * k + 2u] + quarter_counts[4u * k + 3u];
}

void main() {
  uint spare = 0u;  // places of finite ladder bands with no plants
  for (uint k = 0u; k + 1u < ladder_count; ++k) spare += ladder_band_weight(k) == 0u ? 1u : 0u;
  uint band = 0u;
  for (uint k = 0u; k + 1u < ladder_count; ++k) {
    float start = k > 0u ? ladder_ends[k - 1u] : 0.0;
    uint weight = 0u;  // of the band being filled
    for (uint q = 0u; q < 4u; ++q) {
      uint here = quarter_counts[4u * k + q];
      if (q > 0u && weight > 0u && weight + here > dense_plants && spare > 0u) {
        band_ends[band++] = start + (ladder_ends[k] - start) * 0.25 * float(q);
        --spare;
        weight = 0u;
      }
      weight += here;
    }
    if (ladder_band_weight(k) > 0u) band_ends[band++] = ladder_ends[k];  // an empty one joins the next
  }
  for (; band < ladder_count; ++band) band_ends[band] = ladder_ends[ladder_count - 1u];  // to infinity
  for (uint q = 0u; q < 4u * ladder_count; ++q) quarter_counts[q] = 0u;
}
