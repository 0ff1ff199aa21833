// The virtual paged map of --method adaptive (shadow/virtual_map.hpp), as the frame's lighting
// (lighting.glsl) and its page requests (page_requests.comp) see it: each view of the setup is a
// virtual map of page_texels · 2^(page_levels − 1) texels a side, in levels like mipmaps, cut
// into pages; the pages drawn lie each in a layer of the shadow map, with page_guard texels of
// their neighbours around them. The frame addresses page_window pages a side of each level,
// around the camera. Needs shadow_views.glsl.
uniform int page_levels;
uniform float page_texels;
uniform float page_guard;
uniform float page_pixel_texels;
uniform int page_window;
// Where each level's window starts, view by view, level by level (at most 6 views of 16 levels).
uniform ivec2 page_window_origins[96];
// A layer per view's level: the layer holding each page of its window, no_page where none does.
layout(binding = 17) uniform usampler2DArray page_table;
const uint no_page = 0xFFFFFFFFu;

int pages_per_side(int level) { return 1 << (page_levels - 1 - level); }

// World-space size at p of a texel of the virtual map of `view` at `level`.
float page_texel_world_size(int view, int level, vec3 p) {
  return cell_world_size(shadow_matrices[view], vec2(page_texels * float(pages_per_side(level))), p);
}

// The coarsest level whose texels at p are page_pixel_texels or more to a pixel's width.
int wanted_level(int view, vec3 p) {
  float pixel = cell_world_size(view_projection, frame_size, p);
  return clamp(int(floor(log2(pixel / (page_pixel_texels * page_texel_world_size(view, 0, p))))), 0, page_levels - 1);
}

// Where the lookup tests p: moved off the surface along its normal by 1.5 texels of the level
// where the light grazes it, as lighting.glsl moves the lookup of a map.
vec3 page_lookup_position(int view, int level, vec3 p, vec3 n, float n_dot_l) {
  float sin_light = sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0));
  return p + n * (1.5 * page_texel_world_size(view, level, p) * sin_light);
}

// The page of `level` that holds a point at the view's normalized coordinates `ndc`.
ivec2 page_at(vec2 ndc, int level) {
  int side = pages_per_side(level);
  return clamp(ivec2(floor((ndc * 0.5 + 0.5) * float(side))), ivec2(0), ivec2(side - 1));
}

// A page's place in its level's window; outside it where a coordinate is negative or page_window or more.
ivec2 in_window(int view, int level, ivec2 page) { return page - page_window_origins[view * page_levels + level]; }
bool window_holds(ivec2 at) { return all(greaterThanEqual(at, ivec2(0))) && all(lessThan(at, ivec2(page_window))); }

// A page's slot, as shadow::VirtualMap::slot numbers them: view by view, level by level, row by row
// of the level's window.
uint page_slot(int view, int level, ivec2 page) {
  ivec2 at = in_window(view, level, page);
  return uint(((view * page_levels + level) * page_window + at.y) * page_window + at.x);
}

// The finest level at `level` or coarser whose window holds the page at `ndc`.
int addressed_level(int view, vec2 ndc, int level) {
  while (level + 1 < page_levels && !window_holds(in_window(view, level, page_at(ndc, level)))) ++level;
  return level;
}

struct ResidentPage {
  int level;  // negative where no page holds the point
  int layer;
  vec2 map;   // the point's texture coordinates in the layer
};

// The finest page drawn at `level` or coarser that holds a point at `ndc`.
ResidentPage resident_page(int view, vec2 ndc, int level) {
  for (int l = level; l < page_levels; ++l) {
    ivec2 page = page_at(ndc, l);
    ivec2 at = in_window(view, l, page);
    if (!window_holds(at)) continue;
    uint layer = texelFetch(page_table, ivec3(at, view * page_levels + l), 0).r;
    if (layer == no_page) continue;
    vec2 in_page = (ndc * 0.5 + 0.5) * float(pages_per_side(l)) - vec2(page);
    return ResidentPage(l, int(layer), (in_page * page_texels + page_guard) / (page_texels + 2.0 * page_guard));
  }
  return ResidentPage(-1, 0, vec2(0.0));
}
