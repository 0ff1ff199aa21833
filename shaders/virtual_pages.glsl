// The virtual paged map of --method adaptive (shadow/virtual_map.hpp), as the frame's lighting
// (lighting.glsl) and its page requests (page_requests.comp) see it: each view of the setup is a
// virtual map of page_texels · 2^(page_levels − 1) texels a side, in levels like mipmaps, cut
// into pages; the pages drawn lie each in a layer of the shadow map, with page_guard texels of
// their neighbours around them. Needs shadow_views.glsl.
uniform int page_levels;
uniform float page_texels;
uniform float page_guard;
uniform float page_pixel_texels;
// Per view (layer) and level (mip level): the layer holding each page, no_page where none does.
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

// A page's number among every view's, as shadow::VirtualMap::id numbers it: view by view, level by
// level from the finest, row by row.
uint page_id(int view, int level, ivec2 page) {
  uint before = 0u, per_view = 0u;
  for (int l = 0; l < page_levels; ++l) {
    uint pages = uint(pages_per_side(l) * pages_per_side(l));
    if (l < level) before += pages;
    per_view += pages;
  }
  return uint(view) * per_view + before + uint(page.y * pages_per_side(level) + page.x);
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
    uint layer = texelFetch(page_table, ivec3(page, view), l).r;
    if (layer == no_page) continue;
    vec2 in_page = (ndc * 0.5 + 0.5) * float(pages_per_side(l)) - vec2(page);
    return ResidentPage(l, int(layer), (in_page * page_texels + page_guard) / (page_texels + 2.0 * page_guard));
  }
  return ResidentPage(-1, 0, vec2(0.0));
}
