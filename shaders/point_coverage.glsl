// How much of each pixel the frame's points cover, added by splatting pass 1 and read by
// point_surface.frag.
//
// Each point stands for its share of its list's surface (the list's area, its samples' normals'
// w, over the points drawn of it), which covers rho² share |n·v| d / z³ pixels of the image
// (docs/point_density.md). A point in front of the polygons adds that to the entry of its splat's
// lower-left pixel, one atomic a point; a pixel's image area is then the entries of the splats
// that reach it, each over its splat's pixels. Entries are in 1/coverage_steps of a pixel (integer
// atomics), with coverage_margin rows and columns more than the target, as a splat's corner may
// lie that far off its lower or left edge.
layout(binding = 5) uniform sampler2D polygon_depths;  // window depth of the polygons drawn so far
uniform bool polygons_drawn;  // otherwise no polygon hides a point
uniform vec3 eye;
uniform vec3 forward;
uniform float pixels_per_radian;

// The image area point p of draw d stands for, in pixels.
float image_area(uint p, uvec4 d, vec3 world) {
  uint s = d.z + (p - d.x);
  mat4 model = instance_model(d.w);
  vec3 to_eye = eye - world;
  float distance = max(length(to_eye), 1e-6);
  float z = max(-dot(to_eye, forward), 1e-3);
  vec4 normal = sample_normal(s);
  vec3 n = mat3(model) * normal.xyz;  // as long as the model's scale
  float share = normal.w * dot(n, n) / float(d.y);
  float facing = abs(dot(normalize(n), to_eye)) / distance;
  return pixels_per_radian * pixels_per_radian * share * facing * distance / (z * z * z);
}

// Whether a point of this depth in `pixel` is in front of the polygons there.
bool in_front_of_polygons(ivec2 pixel, uint depth) {
  return !polygons_drawn || depth < floatBitsToUint(texelFetch(polygon_depths, pixel, 0).r);
}

// Point p of draw d, in front of the polygons, with a splat from `corner`.
void add_coverage(uint p, uvec4 d, vec3 world, ivec2 corner) {
  ivec2 entry = corner + coverage_margin;
  uint area = uint(round(min(image_area(p, d, world), 16.0) * coverage_steps));
  atomicAdd(coverage[coverage_entry(entry)], area);
}
