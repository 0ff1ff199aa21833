// The point at linear view depth `depth` on the ray through a pixel's centre, as
// app/render/pixel_rays.hpp finds it for the exact reference. Needs camera_position and frame_size
// (shadow_views.glsl).
uniform mat4 pixel_to_world;  // inverse of view_projection
uniform vec3 camera_forward;

vec3 surface_position(vec2 pixel_centre, float depth) {
  vec2 ndc = pixel_centre / frame_size * 2.0 - 1.0;
  vec4 far_point = pixel_to_world * vec4(ndc, 1.0, 1.0);
  vec3 d = normalize(far_point.xyz / far_point.w - camera_position);
  return camera_position + d * (depth / dot(d, camera_forward));
}
