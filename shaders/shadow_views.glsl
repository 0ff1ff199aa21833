// A shadow setup's views as the frame's shaders see them (lighting.glsl, predicted_aliasing.comp):
// the light, which view holds a point's shadow, a texel's size and the aliasing factor.
const int DIRECTIONAL = 0, POINT = 1, SPOT = 2;
uniform int light_type;
uniform vec3 light_position;
uniform vec3 light_direction;  // the way the light travels
uniform float spot_cos_cone;
uniform vec3 camera_position;

// The unit direction from p towards the light.
vec3 direction_to_light(vec3 p) { return light_type == DIRECTIONAL ? -light_direction : normalize(light_position - p); }

// What the frame's shadows need is fixed when the program is built (FramePass::ShadeVariant,
// from the defines SHADOWS, SHADOW_SELECTION, PARABOLOID_VIEWS, ALIASING, MARK_EDGES,
// POINT_LAYERS, SILHOUETTES and VIRTUAL_PAGES): llvmpipe runs both sides of a branch, so code no pixel takes would cost every pixel.
const bool shadows_enabled = SHADOWS;
// The views of the shadow setup (shadow::ShadowSetup), one map layer each, and how a point picks
// its view: one map, cube faces by the major axis of (point - light), the first cascade that
// holds it, or the paraboloid whose hemisphere holds it.
const int SINGLE = 0, CUBE_FACES = 1, FIRST_CONTAINING = 2, HEMISPHERES = 3, SCREEN_MASK = 4;
const int shadow_selection = SHADOW_SELECTION;
const bool paraboloid_views = PARABOLOID_VIEWS;  // whether any view is a paraboloid's
uniform int shadow_view_count;
// A view's world → clip matrix; for a paraboloid view (zoom, range in shadow_paraboloids, zoom 0
// for the others) its world → light space matrix.
uniform mat4 shadow_matrices[6];
uniform vec2 shadow_paraboloids[6];
uniform float shadow_size;  // texels per side
uniform vec2 frame_size;    // pixels
uniform mat4 view_projection;

#include "cascade_square.glsl"
#include "paraboloid.glsl"

vec4 shadow_clip(int layer, vec3 p) {
  if (!paraboloid_views || shadow_paraboloids[layer].x == 0.0) return shadow_matrices[layer] * vec4(p, 1.0);
  return paraboloid_clip(shadow_matrices[layer], shadow_paraboloids[layer], p);
}

// World-space size at p of one cell of a projective matrix's grid of `cells` (the largest of its
// two sides, along the surface or not), from the gradient of the grid coordinates.
float cell_world_size(mat4 m, vec2 cells, vec3 p) {
  vec4 clip = m * vec4(p, 1.0);
  vec3 row_x = vec3(m[0][0], m[1][0], m[2][0]);
  vec3 row_y = vec3(m[0][1], m[1][1], m[2][1]);
  vec3 row_w = vec3(m[0][3], m[1][3], m[2][3]);
  vec3 grad_u = 0.5 * cells.x * (row_x - clip.x / clip.w * row_w) / clip.w;
  vec3 grad_v = 0.5 * cells.y * (row_y - clip.y / clip.w * row_w) / clip.w;
  return 1.0 / max(min(length(grad_u), length(grad_v)), 1e-20);
}

// World-space size of one shadow-map texel at p. For a projective view from the gradient of its
// map coordinates, so it holds for any such parameterization; a paraboloid view is conformal, with
// texels of 2 zoom (1 - d.z) / shadow_size radians (shadow/paraboloid_map.cpp).
float texel_world_size(int layer, vec3 p) {
  vec2 paraboloid = shadow_paraboloids[layer];
  if (paraboloid_views && paraboloid.x != 0.0) {
    vec3 q = (shadow_matrices[layer] * vec4(p, 1.0)).xyz;
    return 2.0 * paraboloid.x * (length(q) - q.z) / shadow_size;
  }
  return cell_world_size(shadow_matrices[layer], vec2(shadow_size), p);
}

#include "virtual_pages.glsl"

// The layer of the map that holds p's shadow.
int shadow_view(vec3 p) {
  if (shadow_selection == SINGLE) return 0;
  if (shadow_selection == FIRST_CONTAINING) {
    for (int i = 0; i < shadow_view_count - 1; ++i) {
      if (in_cascade_square(shadow_matrices[i], p, shadow_size)) return i;
    }
    return shadow_view_count - 1;
  }
  if (shadow_selection == HEMISPHERES) return (shadow_matrices[0] * vec4(p, 1.0)).z <= 0.0 ? 0 : 1;
  vec3 d = p - light_position;
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

// d(ndc.xy)/d(p along t1, t2) of a projective matrix at p: the columns are the two directions.
mat2 screen_jacobian(mat4 m, vec3 p, vec3 t1, vec3 t2) {
  vec4 clip = m * vec4(p, 1.0);
  vec4 d1 = m * vec4(t1, 0.0), d2 = m * vec4(t2, 0.0);
  vec2 ndc = clip.xy / clip.w;
  return mat2((d1.xy - ndc * d1.w) / clip.w, (d2.xy - ndc * d2.w) / clip.w);
}

// The same for the map coordinates of a shadow view. A paraboloid view is projective in the
// direction d = q / |q| (its matrix takes (d, 1) to (d.xy / zoom, -, 1 - d.z)), and d moves by
// the part of a step across it, over |q|.
mat2 shadow_jacobian(int layer, vec3 p, vec3 t1, vec3 t2) {
  mat4 m = shadow_matrices[layer];
  float zoom = shadow_paraboloids[layer].x;
  if (!paraboloid_views || zoom == 0.0) return screen_jacobian(m, p, t1, t2);
  vec3 q = (m * vec4(p, 1.0)).xyz;
  vec3 d = normalize(q);
  vec3 s1 = mat3(m) * t1, s2 = mat3(m) * t2;
  s1 = (s1 - d * dot(d, s1)) / length(q);
  s2 = (s2 - d * dot(d, s2)) / length(q);
  mat4 direction_to_clip = mat4(1.0 / zoom, 0.0, 0.0, 0.0, 0.0, 1.0 / zoom, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0);
  return screen_jacobian(direction_to_clip, d, s1, s2);
}

const bool aliasing_wanted = ALIASING;

// The aliasing factor (docs/figures.md): the size in screen pixels of one shadow-map texel projected
// onto the surface at p with normal n; the largest singular value of pixels per texel along the
// surface. 0 without a shadow map (none, volumes), or when not wanted.
float aliasing_factor(vec3 p, vec3 n) {
  if (!shadows_enabled || !aliasing_wanted || shadow_selection == SCREEN_MASK) return 0.0;
  vec3 t1 = normalize(abs(n.y) < 0.9 ? cross(n, vec3(0.0, 1.0, 0.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
  vec3 t2 = cross(n, t1);
  int view = shadow_view(p);
  float texels_a_side = shadow_size;
  if (VIRTUAL_PAGES) {
    vec4 clip = shadow_matrices[view] * vec4(p, 1.0);
    int level = max(resident_page(view, clip.xy / clip.w, wanted_level(view, p)).level, 0);
    texels_a_side = page_texels * float(pages_per_side(level));
  }
  mat2 texels = 0.5 * texels_a_side * shadow_jacobian(view, p, t1, t2);
  mat2 pixels = mat2(0.5 * frame_size.x, 0.0, 0.0, 0.5 * frame_size.y) * screen_jacobian(view_projection, p, t1, t2);
  float size = dot(texels[0], texels[0]) + dot(texels[1], texels[1]);
  if (abs(determinant(texels)) <= 1e-6 * size) return 1e9;  // the light grazes the surface
  mat2 a = pixels * inverse(texels);
  float frobenius = dot(a[0], a[0]) + dot(a[1], a[1]);
  float d = abs(determinant(a));
  return 0.5 * (sqrt(frobenius + 2.0 * d) + sqrt(max(frobenius - 2.0 * d, 0.0)));
}
