// The lighting of shade.comp: Blinn-Phong with one shadowing light. The shadow term dims the
// diffuse light instead of removing it (Kilgard 2001):
// (ambient + diffuse_shade * diffuse) * albedo + visibility * specular.
#include "shadow_views.glsl"

layout(binding = 0) uniform sampler2DArrayShadow shadow_map;
layout(binding = 1) uniform sampler2D light_mask;  // SCREEN_MASK (shadow volumes): 1 where lit
// SILHOUETTES: per cell of the map's dual grid, a point of the silhouette edge crossing it, as
// silhouette_point.frag writes it; negative where none does.
layout(binding = 16) uniform sampler2DArray silhouette_points;
layout(binding = 18) uniform sampler2DArray silhouette_depths;  // the window depth of each cell's edge

// Low enough that a shadowed surface facing the light keeps about a quarter of its lit colour
// ((0.08 + 0.2) against 1.08), so shadows read in the colour frames as in the PSM paper's figures;
// the dimmed diffuse still shows the curvature of shadowed surfaces.
const float ambient = 0.08;
const float dimming = 0.2;
const float shininess = 48.0;
const float specular_strength = 0.25;
// Hybrid shadows (MARK_EDGES): below this cosine the map's bias, not its depths, decides the test.
const float grazing_n_dot_l = 0.4;

// A cell's silhouette point: negative where no edge crosses the cell (or off the layer's
// `cells` a side).
vec2 silhouette_point(ivec2 cell, int layer, int cells) {
  if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, ivec2(cells)))) return vec2(-1.0);
  return texelFetch(silhouette_points, ivec3(cell, layer), 0).rg;
}

// A neighbour's silhouette point, or its centre, as seen from its neighbour cell `offset` away.
vec2 neighbour_point(ivec2 cell, ivec2 offset, int layer, int cells) {
  vec2 p = silhouette_point(cell + offset, layer, cells);
  return (p.x < 0.0 ? vec2(0.5) : p) + vec2(offset);
}

float cross2(vec2 u, vec2 v) { return u.x * v.y - u.y * v.x; }

// Shadow silhouette maps (Sen, Cammarano and Hanrahan 2003): the map's depths are tested at the
// four corners of the dual-grid cell that holds the surface. Where they agree, that is the answer;
// where they do not and a silhouette edge crosses the cell, the lines from the cell's silhouette
// point to its four neighbours' (their centres where they have none) cut the cell into four
// sectors, one around each corner, and the sector that holds the surface takes its corner's test:
// the edge between lit and shadowed is the silhouette itself, piecewise linear, not the texels'
// staircase. `map.xy`: the surface's texture coordinates in `layer` (`cells` texels a side), which
// keeps the edge where the silhouette puts it; `map.z`: the depth of the surface moved off along
// its normal as the filtered lookup moves it against acne. Negative where the corners disagree and
// no edge crosses the cell (a point splat's shadow): the filtered lookup answers there.
float silhouette_test_at(vec3 map, int layer, int cells) {
  vec2 in_cells = map.xy * float(cells) - 0.5;
  vec2 cell = floor(in_cells);
  // The corners (0, 1), (1, 1), (1, 0), (0, 0), as textureGather orders them.
  vec4 lit = textureGather(shadow_map, vec3((cell + 1.0) / float(cells), layer), map.z);
  if (lit == vec4(lit.x)) return lit.x;
  ivec2 c = ivec2(cell);
  vec2 centre = silhouette_point(c, layer, cells);
  if (centre.x < 0.0) return -1.0;
  vec2 q = in_cells - cell - centre;
  vec2 right = neighbour_point(c, ivec2(1, 0), layer, cells) - centre;
  vec2 up = neighbour_point(c, ivec2(0, 1), layer, cells) - centre;
  vec2 left = neighbour_point(c, ivec2(-1, 0), layer, cells) - centre;
  vec2 down = neighbour_point(c, ivec2(0, -1), layer, cells) - centre;
  // Counter-clockwise from the first line to the second.
  if (cross2(right, q) >= 0.0 && cross2(q, up) >= 0.0) return lit.y;
  if (cross2(up, q) >= 0.0 && cross2(q, left) >= 0.0) return lit.x;
  if (cross2(left, q) >= 0.0 && cross2(q, down) >= 0.0) return lit.w;
  if (cross2(down, q) >= 0.0 && cross2(q, right) >= 0.0) return lit.z;
  // Sectors wider than a half turn (silhouette points on the cell's sides): the nearest corner.
  vec2 f = in_cells - cell;
  return f.y < 0.5 ? (f.x < 0.5 ? lit.w : lit.z) : (f.x < 0.5 ? lit.x : lit.y);
}

// The test in a map's view `layer`; `offset_clip`: the moved surface's clip coordinates (w > 0).
float silhouette_test(int layer, vec3 position, vec4 offset_clip) {
  vec4 clip = shadow_clip(layer, position);
  if (clip.w <= 0.0) return -1.0;
  return silhouette_test_at(vec3(clip.xy / clip.w, offset_clip.z / offset_clip.w) * 0.5 + 0.5, layer, int(shadow_size));
}

// Hybrid shadows: whether a polygon caster's silhouette edge crosses the surface's cell of the
// map's dual grid, nearer the light than the surface and seen by the light (not behind the map's
// depths at all four of the cell's corners). A caster thinner than a texel shadows the surface
// there though no depth sample holds it; the edges of its silhouette, drawn into every cell they
// cross (SilhouettePass), still do.
bool casting_edge_in_cell(vec3 map, int layer, int cells) {
  ivec2 cell = ivec2(floor(map.xy * float(cells) - 0.5));
  if (silhouette_point(cell, layer, cells).x < 0.0) return false;
  float edge = texelFetch(silhouette_depths, ivec3(cell, layer), 0).r;  // the nearest edge's
  if (edge >= map.z) return false;
  vec4 seen = textureGather(shadow_map, vec3((vec2(cell) + 1.0) / float(cells), layer), edge);
  return any(greaterThan(seen, vec4(0.0)));
}

// The mean of 3x3 filtered taps `step` apart around `map` in `layer`.
float filtered_test(vec3 map, int layer, float step) {
  float sum = 0.0;
  for (int y = -1; y <= 1; ++y) {
    for (int x = -1; x <= 1; ++x) {
      sum += texture(shadow_map, vec4(map.xy + vec2(x, y) * step, layer, map.z));
    }
  }
  return sum / 9.0;
}

// --method adaptive: the filtered test below, in the finest page drawn at the level the pixel
// asked for (page_requests.comp) or coarser, its taps a texel of that page's level apart at most;
// with the pages' silhouette maps (adaptive+silhouette), the silhouette test first.
float paged_shadow_test(int view, vec3 position, vec3 n, float n_dot_l) {
  int level = wanted_level(view, position);
  vec4 clip = shadow_matrices[view] * vec4(page_lookup_position(view, level, position, n, n_dot_l), 1.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  if (any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 1.0;  // outside the map: not covered
  ResidentPage page = resident_page(view, ndc.xy, level);
  if (page.level < 0) return 1.0;
  if (SILHOUETTES) {
    // The cell from the surface itself, in the page found for the offset one (its guard holds
    // the cells around it).
    vec4 at = shadow_matrices[view] * vec4(position, 1.0);
    vec2 moved = (at.xy / at.w - ndc.xy) * 0.5 * float(pages_per_side(page.level)) * page_texels / (page_texels + 2.0 * page_guard);
    float edge = silhouette_test_at(vec3(page.map + moved, ndc.z * 0.5 + 0.5), page.layer, int(shadow_size));
    if (edge >= 0.0) return edge;
  }
  float texels_per_pixel = cell_world_size(view_projection, frame_size, position) / page_texel_world_size(view, page.level, position);
  float step = clamp(0.5 * (texels_per_pixel - 1.0), 0.0, 1.0) / shadow_size;
  return filtered_test(vec3(page.map, ndc.z * 0.5 + 0.5), page.layer, step);
}

// Fraction of the light reaching `position` past the occluders in the map: 3x3 taps of
// hardware-filtered comparisons (bilinear PCF), spread over the pixel's footprint in the map: one
// tap's 2x2 texels where a texel is as large as a pixel or larger, up to 4x4 texels where texels
// are 3 pixels to a pixel and more. A wider kernel where texels are large would only blur the
// map, and shadows a texel or two wide (a post's, far off) would fade to lit. The lookup moves off the
// surface along its normal by about a texel where the light grazes it, so the outer taps do not
// hit the surface's own depth (acne); slope-scaled polygon offset in the shadow pass covers the
// centre tap.
float shadow_test(ivec2 pixel, vec3 position, vec3 n, float n_dot_l) {
  if (shadow_selection == SCREEN_MASK) return texelFetch(light_mask, pixel, 0).r;
  int layer = shadow_view(position);
  if (VIRTUAL_PAGES) return paged_shadow_test(layer, position, n, n_dot_l);
  float sin_light = sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0));
  vec3 p = position + n * (1.5 * texel_world_size(layer, position) * sin_light);
  vec4 clip = shadow_clip(layer, p);
  if (clip.w <= 0.0) return 1.0;  // behind the map's projection centre: not covered
  if (SILHOUETTES && !MARK_EDGES) {
    float edge = silhouette_test(layer, position, clip);
    if (edge >= 0.0) return edge;
  }
  vec3 map = clip.xyz / clip.w * 0.5 + 0.5;
  if (any(lessThan(map.xy, vec2(0.0))) || any(greaterThan(map.xy, vec2(1.0)))) return 1.0;
  float texels_per_pixel = cell_world_size(view_projection, frame_size, position) / texel_world_size(layer, position);
  float step = clamp(0.5 * (texels_per_pixel - 1.0), 0.0, 1.0) / shadow_size;
  if (MARK_EDGES) {
    // Hybrid shadows. The point splats, in layers of their own after the views' (POINT_LAYERS),
    // cast no volumes: their shadows are the map's, lit or not. Then the polygons': neither lit
    // nor shadowed, for the volumes to decide, where the light grazes the surface, where a casting
    // silhouette edge crosses its cell, or where taps a texel apart disagree (so that an edge
    // the normal offset moved, up to 1.5 texels, still falls among them).
    if (POINT_LAYERS && filtered_test(map, shadow_view_count + layer, step) < 0.5) return 0.0;
    if (n_dot_l < grazing_n_dot_l) return 0.5;
    if (SILHOUETTES) {
      // At the surface's own point: the offset one may step past the thin shadows only the edges show.
      vec4 own = shadow_clip(layer, position);
      if (own.w > 0.0 && casting_edge_in_cell(own.xyz / own.w * 0.5 + 0.5, layer, int(shadow_size))) return 0.5;
    }
    step = 1.0 / shadow_size;
  }
  return filtered_test(map, layer, step);
}

vec3 linear_to_srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

struct Shading {
  vec3 color;        // linear RGB
  float visibility;  // the `shadow` AOV
};

// `n` faces the viewer (thin surfaces are lit from either side); `position` is what `pixel` shows.
Shading shade(ivec2 pixel, vec3 position, vec3 n, vec3 albedo) {
  vec3 to_light = direction_to_light(position);
  float n_dot_l = dot(n, to_light);

  float cone = 1.0;
  float falloff = 1.0;
  if (light_type == SPOT) {
    float cos_angle = dot(-to_light, light_direction);
    cone = cos_angle >= spot_cos_cone ? 1.0 : 0.0;
    falloff = smoothstep(spot_cos_cone, mix(spot_cos_cone, 1.0, 0.25), cos_angle);
  }
  float visibility = n_dot_l > 0.0 ? cone : 0.0;
  if (shadows_enabled && visibility > 0.0) visibility *= shadow_test(pixel, position, n, n_dot_l);

  vec3 view_dir = normalize(camera_position - position);
  vec3 half_dir = normalize(to_light + view_dir);
  float diffuse = max(n_dot_l, 0.0) * falloff;
  float specular = n_dot_l > 0.0 ? specular_strength * pow(max(dot(n, half_dir), 0.0), shininess) * falloff : 0.0;
  float diffuse_shade = dimming + (1.0 - dimming) * visibility;
  return Shading((ambient + diffuse_shade * diffuse) * albedo + visibility * specular, visibility);
}
