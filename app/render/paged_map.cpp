#include "app/render/paged_map.hpp"

#include "app/render/shadow_pass.hpp"

#include <algorithm>

namespace ecoview {
namespace {

constexpr int most_views = 6;  // a cube's faces
constexpr GLuint flags_binding = 27, list_binding = 28;  // shaders/page_requests.comp

bool same_views(const std::vector<shadow::ShadowView>& a, const std::vector<shadow::ShadowView>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].view != b[i].view || a[i].projection != b[i].projection) return false;
  }
  return true;
}

}  // namespace

int PagedMap::most_layers() {
  GLint layers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
  return layers;
}

PagedMap::PagedMap(const shadow::VirtualMap& map, int layers, GLenum depth_format, bool silhouettes)
    : map_(map), pool_(map, layers) {
  const GLuint pages = pages_.name();
  glTextureStorage3D(pages, 1, depth_format, map.layer_texels(), map.layer_texels(), pool_.layers());
  make_comparable(pages);  // the guard keeps the filter on its page's layer
  if (silhouettes) {
    glTextureStorage3D(silhouettes_.emplace(GL_TEXTURE_2D_ARRAY).name(), 1, GL_RG16F, map.layer_texels(), map.layer_texels(), pool_.layers());
  }

  glTextureStorage3D(table_.name(), 1, GL_R32UI, map.window, map.window, most_views * map.levels);
  glTextureParameteri(table_.name(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(table_.name(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);

  const std::size_t every_slot = static_cast<std::size_t>(map.slots_per_view()) * most_views;
  zeros_.assign(every_slot, 0u);
  gl::store(flags_, zeros_, GL_DYNAMIC_STORAGE_BIT);
  gl::store(list_, std::vector<GLuint>(every_slot + 1, 0u), GL_DYNAMIC_STORAGE_BIT);
}

void PagedMap::request(const FramePass& frame, const shadow::Camera& camera, const shadow::Light& light,
                       const shadow::ShadowSetup& setup, bool points_follow_camera) {
  if (!same_views(setup.views, views_)) {
    pool_.clear();
    views_ = setup.views;
  }
  const int views = std::min(static_cast<int>(setup.views.size()), most_views);
  origins_ = map_.window_origins({setup.views.begin(), setup.views.begin() + views}, camera.position);
  const auto slots = static_cast<std::size_t>(map_.slots_per_view()) * static_cast<std::size_t>(views);
  // Uploaded, not cleared: on llvmpipe a clear could land after the pass behind it.
  glNamedBufferSubData(flags_.name(), 0, static_cast<GLsizeiptr>(slots * sizeof(GLuint)), zeros_.data());
  const GLuint none = 0;
  glNamedBufferSubData(list_.name(), 0, sizeof none, &none);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, flags_binding, flags_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, list_binding, list_.name());
  FramePass::ShadowLookup asking{pages_.name(), setup, map_.layer_texels()};
  asking.page_table = table_.name();  // last frame's: the requests read only the map's shape
  asking.pages = map_;
  asking.page_windows = origins_;
  frame.request_pages(camera, light, asking);

  GLuint count = 0;
  glGetNamedBufferSubData(list_.name(), 0, sizeof count, &count);
  std::vector<std::uint32_t> ids(std::min<std::size_t>(count, slots));
  if (!ids.empty()) {
    glGetNamedBufferSubData(list_.name(), sizeof count, static_cast<GLsizeiptr>(ids.size() * sizeof(GLuint)), ids.data());
  }
  for (std::uint32_t& id : ids) id = map_.id(map_.slot_page(id, origins_));
  // Every view's coarsest page, one for the whole map: the lookup's last resort.
  for (int v = 0; v < views; ++v) ids.push_back(map_.id({v, map_.levels - 1, 0, 0}));
  if (points_follow_camera) {
    // A page's points were chosen for the camera it was drawn from: once the camera has moved a
    // page's width of its level across the view's image (a fifth of the distance at which pixels ask
    // for that level), the page is drawn again with the points chosen now.
    pool_.invalidate([&](const shadow::Page& p, const glm::vec3& drawn_from) {
      if (p.view >= views || drawn_from == camera.position) return false;
      const shadow::ShadowView& view = setup.views[static_cast<std::size_t>(p.view)];
      const glm::vec4 then = view.clip(drawn_from), now = view.clip(camera.position);
      if (then.w <= 0.0f || now.w <= 0.0f) return true;
      const glm::vec2 moved = glm::abs(glm::vec2(now) / now.w - glm::vec2(then) / then.w);
      return std::max(moved.x, moved.y) * static_cast<float>(map_.pages_per_side(p.level)) > 2.0f;
    });
  }
  frame_ = pool_.update(ids, camera.position);
}

void PagedMap::invalidate(const std::vector<std::vector<glm::vec4>>& moved) {
  const float guard = static_cast<float>(map_.guard) / static_cast<float>(map_.page_texels);
  pool_.invalidate([&](const shadow::Page& p, const glm::vec3&) {
    if (p.view >= static_cast<int>(moved.size())) return false;
    const float side = static_cast<float>(map_.pages_per_side(p.level));
    const glm::vec2 low = glm::vec2(-1.0f) + 2.0f * (glm::vec2(p.x, p.y) - guard) / side;
    const glm::vec2 high = glm::vec2(-1.0f) + 2.0f * (glm::vec2(p.x, p.y) + 1.0f + guard) / side;
    for (const glm::vec4& box : moved[static_cast<std::size_t>(p.view)]) {
      if (box.x <= high.x && box.z >= low.x && box.y <= high.y && box.w >= low.y) return true;
    }
    return false;
  });
}

void PagedMap::copy_pages(GLuint tile_map, GLuint tile_silhouettes, const shadow::PageTile& tile) const {
  const int side = map_.layer_texels();
  for (const auto& [page, layer] : frame_.to_draw) {
    if (!tile.holds(page)) continue;
    const glm::ivec2 corner = map_.page_corner(tile, page);
    glCopyImageSubData(tile_map, GL_TEXTURE_2D_ARRAY, 0, corner.x, corner.y, 0, pages_.name(), GL_TEXTURE_2D_ARRAY, 0, 0, 0,
                       layer, side, side, 1);
    if (silhouettes_) {
      glCopyImageSubData(tile_silhouettes, GL_TEXTURE_2D_ARRAY, 0, corner.x, corner.y, 0, silhouettes_->name(), GL_TEXTURE_2D_ARRAY, 0, 0, 0,
                         layer, side, side, 1);
    }
  }
}

FramePass::ShadowLookup PagedMap::lookup(const shadow::ShadowSetup& setup) {
  upload_table(std::min(static_cast<int>(setup.views.size()), most_views));
  FramePass::ShadowLookup lookup{pages_.name(), setup, map_.layer_texels()};
  lookup.page_table = table_.name();
  lookup.pages = map_;
  lookup.page_windows = origins_;
  if (silhouettes_) lookup.silhouettes = silhouettes_->name();
  return lookup;
}

// A layer a view's level, as the slots are numbered; the pages held outside this frame's windows
// stay in the pool, out of the table.
void PagedMap::upload_table(int views) {
  std::vector<GLuint> table(static_cast<std::size_t>(map_.slots_per_view()) * static_cast<std::size_t>(views), 0xFFFFFFFFu);
  for (const auto& [id, layer] : pool_.held()) {
    if (const auto slot = map_.slot(map_.page(id), origins_); slot && *slot < table.size()) table[*slot] = static_cast<GLuint>(layer);
  }
  glTextureSubImage3D(table_.name(), 0, 0, 0, 0, map_.window, map_.window, views * map_.levels, GL_RED_INTEGER, GL_UNSIGNED_INT,
                      table.data());
}

}  // namespace ecoview
