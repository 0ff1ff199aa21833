#version 450 core
// The GPU sampler's first passes, once a frame: the plants in view sorted into distance bands,
// each band's in plant order (a stable counting sort). With HISTOGRAM the plants in the view's
// frusta weighed by quarters of the ladder's bands (band_ends.comp cuts the dense ones there).
// With KEYS each plant culled against the view's frusta and given its band by its distance from
// the eye; a plant in none of them but in the body of the casters (what may shadow the view) goes
// to the last band, the casters'; with HIDDEN_KEYS, once the frame's bands are counted, the
// plants the nearest of them left out as hidden, and the polygon plants the map takes as points,
// go to a band of their own. Then each work group of plants counts (COUNT) or places its plants
// band by band, one thread walking the group's plants in order. The keys pass also clears the
// plants' counts.
#include "sample_common.glsl"

layout(std430, binding = 22) buffer BandKeys { uint band_keys[]; };  // per plant: its band from 0, or no_band
// Per band and group of plants (band-major): its plants there, then (sample_bands.comp) their
// first place in the band list.
layout(std430, binding = 23) buffer GroupBands { uint group_bands[]; };
uniform uint group_count;
uniform uint band_count;
// The frame's distance bands' far ends, metres (band_ends.comp), and the plants in view per
// quarter of the ladder's bands.
layout(std430, binding = 34) buffer BandEnds {
  float band_ends[32];
  uint quarter_counts[];
};

#ifdef HIDDEN_KEYS
layout(local_size_x = 256) in;
uniform float hidden_reach;  // metres: the bands that end within it
// The map's view, its texels, k and a point's cost in triangles: a plant the frame draws as
// polygons that the map asks fewer points of than would be cheaper as polygons goes into the
// band too, as points (a coarse texel is shadowed only where its centre meets a polygon's leaf,
// but wholly by a point's splat).
uniform mat4 map_view_projection;
uniform float map_texels;
uniform float k;
uniform float points_per_triangle;
uniform bool polygons_to_points;  // off: the map draws every polygon plant (GpuSampler::add_casters)

bool map_takes_points(uint i) {
  mat4 model = instance_model(i);
  SampledMesh mesh = plant_mesh(i);
  vec3 center = (model * vec4(mesh.center_radius.xyz, 1.0)).xyz;
  float scale = model_scale(model);
  float asked = points_a_map_asks(map_view_projection, map_texels, k, center, mesh.half_size_area.w * scale * scale);
  return !as_polygons(asked, mesh, points_per_triangle);
}
// The plants in view that those bands left out as hidden (sample_count.comp) and the polygon
// plants the map takes as points, into one band.
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= plant_count) return;
  Count c = count_of(i);
  bool hidden = c.hidden && band_ends[c.band - 1u] <= hidden_reach;
  band_keys[i] = hidden || (polygons_to_points && c.polygons && c.points == 0u && map_takes_points(i)) ? 0u : no_band;
}
#elif defined(KEYS) || defined(HISTOGRAM)
layout(local_size_x = 256) in;
uniform vec4 planes[96];  // inside where dot >= 0: six per view, then the casters' body's
uniform uint view_count;
uniform uint caster_plane_count;  // none: no casters' band
uniform vec3 eye;

bool in_planes(vec3 center, float radius, uint first, uint end) {
  bool inside = true;
  for (uint p = first; p < end; ++p) inside = inside && dot(planes[p].xyz, center) + planes[p].w >= -radius;
  return inside;
}

bool in_view(vec3 center, float radius) {
  for (uint v = 0u; v < view_count; ++v) {
    if (in_planes(center, radius, 6u * v, 6u * v + 6u)) return true;
  }
  return false;
}

#ifdef HISTOGRAM
uniform float ladder_ends[32];  // the ladder's bands' far ends (GpuSampler::bands), the last's infinite
uniform uint ladder_count;
// The count's view (sample_count.comp): a plant likely drawn as polygons (before occlusion) weighs
// a plant per triangles_a_plant of its triangles, for the plants of one band do not hide each other
// and polygons cost most.
uniform vec3 forward;
uniform float edge_cos;
uniform float pixels_per_radian;
uniform float k;
uniform float points_per_triangle;
const uint triangles_a_plant = 128u;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= plant_count || !holds_plant(i)) return;
  mat4 model = instance_model(i);
  vec4 bounds = plant_mesh(i).center_radius;
  vec3 center = (model * vec4(bounds.xyz, 1.0)).xyz;
  if (!in_view(center, bounds.w * model_scale(model))) return;
  float from_eye = length(eye - center);
  uint band = 0u;
  while (band + 1u < ladder_count && from_eye >= ladder_ends[band]) ++band;
  uint quarter = 0u;
  if (band + 1u < ladder_count) {
    float start = band > 0u ? ladder_ends[band - 1u] : 0.0;
    quarter = min(uint(4.0 * (from_eye - start) / (ladder_ends[band] - start)), 3u);
  }
  SampledMesh mesh = plant_mesh(i);
  float needed = points_needed(model, mesh, eye, forward, edge_cos, pixels_per_radian, k);
  uint weight = as_polygons(needed, mesh, points_per_triangle) ? max(mesh.sizes.x / triangles_a_plant, 1u) : 1u;
  atomicAdd(quarter_counts[4u * band + quarter], weight);
}
#else
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= plant_count) return;
  counts[i] = 0u;
  band_keys[i] = no_band;
  if (!holds_plant(i)) return;  // a pool's empty place joins no band
  mat4 model = instance_model(i);
  vec4 bounds = plant_mesh(i).center_radius;
  vec3 center = (model * vec4(bounds.xyz, 1.0)).xyz;
  float radius = bounds.w * model_scale(model);
  uint key = no_band;
  uint distance_bands = caster_plane_count > 0u ? band_count - 1u : band_count;
  if (in_view(center, radius)) {
    float from_eye = length(eye - center);
    key = 0u;
    while (key + 1u < distance_bands && from_eye >= band_ends[key]) ++key;
  } else if (caster_plane_count > 0u && in_planes(center, radius, 6u * view_count, 6u * view_count + caster_plane_count)) {
    key = band_count - 1u;
  }
  band_keys[i] = key;
}
#endif
#else
layout(local_size_x = 64) in;
#define MAX_BANDS 32

void main() {
  uint group = gl_GlobalInvocationID.x;
  if (group >= group_count) return;
  uint next[MAX_BANDS];
  for (uint b = 0u; b < band_count; ++b) next[b] = 0u;
  uint end = min((group + 1u) * plants_per_group, plant_count);
#ifdef COUNT
  for (uint i = group * plants_per_group; i < end; ++i) {
    uint key = band_keys[i];
    if (key != no_band) ++next[key];
  }
  for (uint b = 0u; b < band_count; ++b) group_bands[b * group_count + group] = next[b];
#else
  for (uint b = 0u; b < band_count; ++b) next[b] = group_bands[b * group_count + group];
  for (uint i = group * plants_per_group; i < end; ++i) {
    uint key = band_keys[i];
    if (key != no_band) band_list[next[key]++] = i;
  }
#endif
}
#endif
