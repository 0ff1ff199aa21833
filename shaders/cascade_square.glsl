// Whether a point looks up the cascade of world → clip matrix `m` (ViewSelection::first_containing):
// it lies in that cascade's box at least CASCADE_MARGIN_TEXELS texels of a `map_texels`-wide map
// inside its square. The shading and the cascades' receiver masks decide by this one rule.
const float CASCADE_MARGIN_TEXELS = 2.0;  // shadow::cascade_margin_texels

bool in_cascade_square(mat4 m, vec3 p, float map_texels) {
  float inside = 1.0 - 2.0 * CASCADE_MARGIN_TEXELS / map_texels;
  vec4 clip = m * vec4(p, 1.0);
  return all(lessThanEqual(abs(clip.xy), vec2(inside * clip.w))) && abs(clip.z) <= clip.w;
}
