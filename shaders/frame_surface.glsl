// The frame's surface at a pixel: the nearest splatted point where the point pass added one in
// front of the polygons (point_surface.frag, into targets of its own), else the polygons' own
// (surface.frag). Kept apart, the polygons' surface is at hand behind a point that covers only
// part of its pixel, with no copy of it (which took 1.5 ms of a 1080p frame on an H200 as
// glCopyImageSubData, 12 ms of a 960 × 540 one on llvmpipe as a compute copy).
layout(binding = 2) uniform sampler2D polygon_normals;  // world, facing the viewer
layout(binding = 3) uniform sampler2D polygon_albedos;  // linear RGB, alpha 1
layout(binding = 4) uniform sampler2D polygon_depths;   // linear view depth, negative for none
layout(binding = 5) uniform sampler2D point_normals;
layout(binding = 6) uniform sampler2D point_albedos;    // alpha: the share of the pixel the points cover
layout(binding = 7) uniform sampler2D point_depths;     // negative where no point was added
uniform bool points_added;                              // this frame

struct Surface {
  float depth;  // linear view depth, negative for none (the sky)
  vec3 normal;
  vec4 albedo;
};

Surface frame_surface(ivec2 pixel) {
  if (points_added) {
    float depth = texelFetch(point_depths, pixel, 0).r;
    if (depth >= 0.0) return Surface(depth, texelFetch(point_normals, pixel, 0).xyz, texelFetch(point_albedos, pixel, 0));
  }
  return Surface(texelFetch(polygon_depths, pixel, 0).r, texelFetch(polygon_normals, pixel, 0).xyz,
                 texelFetch(polygon_albedos, pixel, 0));
}
