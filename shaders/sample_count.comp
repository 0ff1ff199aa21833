#version 450 core
// The GPU sampler's first pass: each plant culled against the view's frusta and counted with the
// density formula (docs/point_density.md), points or polygons chosen as pointgen::sample_view
// chooses them without occlusion; then the prefix sums of the counts within each work group.
#include "sample_common.glsl"
layout(local_size_x = 256) in;

uniform vec4 planes[36];  // six per view, inside where dot >= 0
uniform uint view_count;
uniform vec3 eye;
uniform vec3 forward;
uniform float edge_cos;
uniform float pixels_per_radian;
uniform float k;
uniform float points_per_triangle;

// The band around break-even (pointgen/sampling/view_sampler.cpp).
const float band_low = 0.8, band_high = 1.25;

bool in_view(vec3 center, float radius) {
  for (uint v = 0u; v < view_count; ++v) {
    bool inside = true;
    for (uint p = 0u; p < 6u; ++p) inside = inside && dot(planes[6u * v + p].xyz, center) + planes[6u * v + p].w >= -radius;
    if (inside) return true;
  }
  return false;
}

float facing(SampledMesh mesh, vec3 v) {
  mat3 moments = mat3(mesh.moments[0].xyz, mesh.moments[1].xyz, mesh.moments[2].xyz);
  if (!(moments[0][0] + moments[1][1] + moments[2][2] > 0.0)) return 0.5;
  return sqrt(max(dot(v, moments * v), 0.0));
}

// (points, 1 when drawn as polygons) of plant i.
uvec2 count_plant(uint i) {
  if (i >= plant_count) return uvec2(0u);
  mat4 model = instances[i].model;
  SampledMesh mesh = meshes[plant_meshes[i].x];
  float scale = pow(abs(determinant(mat3(model))), 1.0 / 3.0);
  vec3 center = (model * vec4(mesh.center_radius.xyz, 1.0)).xyz;
  float radius = mesh.center_radius.w * scale;
  if (!in_view(center, radius)) return uvec2(0u);
  float distance = max(length(eye - center), max(0.5 * radius, 1e-3));
  float depth = max(dot(center - eye, forward), distance * edge_cos);
  vec3 to_eye = inverse(mat3(model)) * (eye - center);
  float facing_eye = dot(to_eye, to_eye) > 0.0 ? facing(mesh, normalize(to_eye)) : 0.5;
  float z = max(depth, 1e-3);
  float needed = k * pixels_per_radian * pixels_per_radian * mesh.area.x * scale * scale * facing_eye * max(distance, z) / (z * z * z);
  float samples = float(mesh.sizes.y);
  float ratio = needed / (points_per_triangle * float(mesh.sizes.x));
  bool as_polygons = ratio > band_low || needed > samples;
  float drawn = (as_polygons ? clamp((band_high - ratio) / (band_high - band_low), 0.0, 1.0) : 1.0) * needed;
  uint points = uint(min(floor(drawn + uintBitsToFloat(plant_meshes[i].y)), samples));
  bool as_points = ratio < band_high && mesh.sizes.y > 0u;
  return uvec2(as_points ? points : 0u, as_polygons ? 1u : 0u);
}

shared uvec2 sums[256];

void main() {
  uint first = gl_WorkGroupID.x * plants_per_group + gl_LocalInvocationID.x * 4u;
  uvec2 own[4];
  uvec2 total = uvec2(0u);
  for (uint j = 0u; j < 4u; ++j) {
    uvec2 c = count_plant(first + j);
    own[j] = total;
    total += uvec2(c.x, c.x > 0u ? 1u : 0u);
    if (first + j < plant_count) counts[first + j] = c;
  }
  // Inclusive scan of the threads' totals (Hillis-Steele), then each plant's exclusive offset.
  uint t = gl_LocalInvocationID.x;
  sums[t] = total;
  barrier();
  for (uint step = 1u; step < 256u; step *= 2u) {
    uvec2 before = t >= step ? sums[t - step] : uvec2(0u);
    barrier();
    sums[t] += before;
    barrier();
  }
  uvec2 thread_offset = sums[t] - total;
  for (uint j = 0u; j < 4u; ++j) {
    if (first + j < plant_count) offsets[first + j] = thread_offset + own[j];
  }
  if (t == 255u) group_sums[gl_WorkGroupID.x] = sums[t];
}
