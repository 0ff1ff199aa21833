#include "pointgen/sampling/view_sampler.hpp"

#include "pointgen/random.hpp"
#include "pointgen/sampling/coverage_grid.hpp"
#include "pointgen/sampling/frustum_culling.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <tuple>

namespace pointgen {
namespace {

// The band around break-even, as ratios of needed points to the polygon-equivalent count, in which
// an instance is drawn both as points and as polygons: its polygons whole, its points thinning out
// over them, from its full count at the bottom of the band to none at the top.
constexpr float band_low = 0.8f, band_high = 1.25f;
// An instance certainly drawn as points whose screen rectangle spans more pixels than this is
// counted by parts.
constexpr float pixels_to_split = 1024.0f;
// A cell, instance or part is skipped when nearer objects leave less than this of its screen
// rectangle uncovered.
constexpr float hidden_transmittance = 0.001f;
// A cell is counted as one object when its box is smaller than this times its distance.
constexpr float aggregate_radius = 0.2f;

// What is counted, hidden and drawn as one: an instance inside one of the views, or a part of it.
struct Candidate {
  std::uint32_t table = 0, instance = 0;
  const MeshPart* part = nullptr;  // none: the whole instance
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  float area = 0.0f;   // square metres
  float order = 0.0f;  // depth in the first view: sorted front to back
};

// The screen rectangle of an instance's or a part's box.
std::optional<CoverageGrid::Rect> rect_of(const CoverageGrid& grid, const Candidate& c, const SampledMesh& mesh,
                                          const glm::mat4& transform) {
  return c.part ? grid.project(c.part->center, c.part->half_size, transform) : grid.project(mesh.center, mesh.half_size, transform);
}

float polygon_equivalent(const SamplerView& view, const SampledMesh& mesh) {
  return view.points_per_triangle * static_cast<float>(mesh.triangles);
}

// Points for k per pixel of the candidate's surface, before anything hides it. With the cap, the
// coverage grid is the map's image.
float unoccluded_count(const SamplerView& view, const CoverageGrid* coverage, const Candidate& c, const SampledMesh& mesh,
                       const glm::mat4& transform) {
  // Distances to the centre: the count is right on average over the object (docs/point_density.md).
  const float distance = std::max(glm::distance(view.eye, c.center), std::max(0.5f * c.radius, 1e-3f));
  const float depth = std::max(glm::dot(c.center - view.eye, view.forward), distance * view.edge_cos);
  // How much its surface faces the eye, in the mesh's frame.
  const glm::vec3 to_eye = glm::inverse(glm::mat3(transform)) * (view.eye - c.center);
  const glm::mat3& moments = c.part ? c.part->normal_moments : mesh.normal_moments;
  const float facing_eye = glm::dot(to_eye, to_eye) > 0.0f ? facing(moments, glm::normalize(to_eye)) : 0.5f;
  float needed = points_needed(view.density, c.area, depth, distance, facing_eye);
  if (coverage && view.cap_to_pixels) {
    // Towards the light, surface is taken as facing every way: half its area projects.
    const float ndc_to_pixels = 0.25f * static_cast<float>(view.pixels.x) * static_cast<float>(view.pixels.y);
    needed = std::min(needed, view.density.k * 0.5f * c.area * coverage->ndc_area_per_square_metre(c.center) * ndc_to_pixels);
  }
  return needed;
}

// Whether an instance is counted by parts: when it is certainly drawn as points (whatever hides
// it, it stays below the band) and its screen rectangle is large, so that its front can hide its back.
bool counted_by_parts(const SamplerView& view, const CoverageGrid& coverage, const SampledMesh& mesh, const glm::mat4& transform,
                      const Candidate& whole) {
  if (mesh.parts.empty() || mesh.sample_positions.empty()) return false;
  // The size first: most instances are small, and their counts are taken once, in sample_view.
  const std::optional<CoverageGrid::Rect> rect = coverage.project(mesh.center, mesh.half_size, transform);
  if (!rect || !(coverage.cells_in(*rect) > pixels_to_split)) return false;
  const float needed = unoccluded_count(view, &coverage, whole, mesh, transform);
  return needed < std::min(band_low * polygon_equivalent(view, mesh), static_cast<float>(mesh.samples));
}

// The share of its points an object keeps when objects in front hide `transmittance` of its screen
// rectangle on average. Its points are a prefix of a list spread over all of it, so they cannot
// follow which part is hidden: it keeps its full count until nearly all of its rectangle is hidden
// and only then fades out.
float visible_share(float transmittance, float full_count_transmittance) {
  return std::min(1.0f, transmittance / full_count_transmittance);
}

// Covers the splats of the first `drawn` of an object's samples from `first` in its mesh's list,
// but of no more than one per pixel of its rectangle: more add no coverage.
void cover(CoverageGrid& coverage, const SampledMesh& mesh, std::uint32_t first, const glm::mat4& transform,
           const CoverageGrid::Rect& rect, std::size_t drawn) {
  const auto enough = static_cast<std::size_t>(coverage.cells_in(rect)) + 1;
  const std::span<const glm::vec3> list = std::span(mesh.sample_positions).subspan(std::min<std::size_t>(first, mesh.sample_positions.size()));
  coverage.cover(list.first(std::min({drawn, enough, list.size()})), transform);
}

// Covers the cells an instance's polygons cover, as far as its sample list tells: each sample the
// cell it falls in (a splat's worth would close the gaps between leaves that show what is behind),
// up to one sample per cell of its rectangle. A large one part by part, skipping those whose
// cells are already covered (a near tree behind others: most of its list).
void cover_polygons(CoverageGrid& coverage, const SampledMesh& mesh, const glm::mat4& transform, const CoverageGrid::Rect& rect) {
  const std::span<const glm::vec3> list(mesh.sample_positions);
  const auto cover_prefix = [&](std::size_t first, std::size_t samples, const CoverageGrid::Rect& r) {
    const auto enough = static_cast<std::size_t>(coverage.cells_in(r)) + 1;
    coverage.cover_surface(list.subspan(first, std::min({enough, samples, list.size() - first})), transform);
  };
  if (mesh.parts.empty() || !(coverage.cells_in(rect) > pixels_to_split)) {
    cover_prefix(0, mesh.samples, rect);
    return;
  }
  for (const MeshPart& part : mesh.parts) {
    const std::optional<CoverageGrid::Rect> part_rect = coverage.project(part.center, part.half_size, transform);
    if (!part_rect || !part_rect->on_screen() || coverage.transmittance(*part_rect) < hidden_transmittance) continue;
    cover_prefix(part.first, part.samples, *part_rect);
  }
}

// The candidate's threshold in [0, 1) for rounding its count: fixed per instance and part.
float rounding(const InstanceTable& table, const Candidate& c, const SampledMesh& mesh) {
  if (table.rounds_up) return InstanceTable::round_up_threshold;
  const std::uint64_t seed = table.seeds.size() > c.instance ? table.seeds[c.instance] : c.instance;
  return Random(c.part ? derive_seed(seed, static_cast<std::uint64_t>(c.part - mesh.parts.data()) + 1) : seed).uniform();
}

// The depth order of a point in the first view: its NDC depth, -infinity behind the eye.
float depth_order(const SamplerView& view, const glm::vec3& p) {
  const glm::vec4 clip = view.views.front() * glm::vec4(p, 1.0f);
  return clip.w > 0.0f ? clip.z / clip.w : -INFINITY;
}

std::optional<CoverageGrid::Rect> rect_of(const CoverageGrid& grid, const InstanceCell& cell) {
  return grid.project(0.5f * (cell.min + cell.max), 0.5f * (cell.max - cell.min), glm::mat4(1.0f));
}

// One view's sampling: cells front to back, each opened into its instances (or parts), hidden as
// a whole, or counted as a whole when far; the instances of the open cells in exact front-to-back
// order, each counted, drawn and added to the coverage grid.
class ViewSampling {
 public:
  ViewSampling(const SamplerView& view, const TableList& tables, const std::vector<SampledMesh>& meshes)
      : view_(view), tables_(tables), meshes_(meshes), frusta_(view.views) {
    frame_.polygons.resize(tables.size());
    frame_.polygon_parts.resize(tables.size());
    // Occlusion and the cap need one image; several views (cube maps) count every instance whole.
    if ((view.occlusion || view.cap_to_pixels) && view.views.size() == 1) coverage_.emplace(view.views.front(), view.pixels, view.splat_pixels);
    if (coverage_ && view.occlusion) occlusion_ = &*coverage_;
  }

  SampledFrame run(const InstanceCells& cells) {
    struct Seen {
      const InstanceCell* cell;
      float order;
    };
    std::vector<Seen> seen;
    for (const std::vector<InstanceCell>& table_cells : cells.by_table()) {
      for (const InstanceCell& cell : table_cells) {
        if (!box_in_view(cell) || !shadows_receivers(0.5f * (cell.min + cell.max), 0.5f * (cell.max - cell.min), glm::mat4(1.0f))) continue;
        float order = INFINITY;
        for (int i = 0; i < 8; ++i) {
          const glm::vec3 corner((i & 1) ? cell.max.x : cell.min.x, (i & 2) ? cell.max.y : cell.min.y, (i & 4) ? cell.max.z : cell.min.z);
          order = std::min(order, depth_order(view_, corner));
        }
        seen.push_back({&cell, order});
      }
    }
    std::sort(seen.begin(), seen.end(), [](const Seen& a, const Seen& b) {
      return std::tie(a.order, a.cell->table, a.cell->members.front()) < std::tie(b.order, b.cell->table, b.cell->members.front());
    });
    // A cell's instances lie behind its box's nearest corner: those queued in front of it go first.
    for (const Seen& s : seen) {
      while (!open_.empty() && open_.front().front().order < s.order) add_next();
      // Hidden: nearer objects leave too little of its rectangle uncovered (docs/point_density.md, "Cells").
      const std::optional<CoverageGrid::Rect> rect = occlusion_rect(*s.cell);
      const float transmittance = rect ? occlusion_->transmittance(*rect) : 1.0f;
      if (transmittance < hidden_transmittance || add_as_aggregate(*s.cell, rect, transmittance)) continue;
      open(*s.cell);
    }
    while (!open_.empty()) add_next();
    return std::move(frame_);
  }

 private:
  // Front to back; ties in a fixed order.
  static bool before(const Candidate& a, const Candidate& b) {
    return std::tie(a.order, a.table, a.instance, a.part) < std::tie(b.order, b.table, b.instance, b.part);
  }
  // An open cell's candidates in view, sorted, and the next one to add. The open cells make a
  // heap by their next candidate: a merge of sorted lists, which stays small and in cache where
  // one heap of every candidate would not (a 2048² shadow map's view of 10^5 trees by parts
  // holds millions).
  struct OpenCell {
    std::vector<Candidate> candidates;
    std::size_t next = 0;
    const Candidate& front() const { return candidates[next]; }
  };
  static bool later(const OpenCell& a, const OpenCell& b) { return before(b.front(), a.front()); }

  // Whether a box (centre and half sizes, placed by `transform`) may shadow what the camera saw:
  // always without a receiver mask.
  bool shadows_receivers(const glm::vec3& center, const glm::vec3& half_size, const glm::mat4& transform) const {
    return !view_.receivers || view_.receivers->may_shadow(center, half_size, transform);
  }

  bool box_in_view(const InstanceCell& cell) const {
    const glm::vec3 center = 0.5f * (cell.min + cell.max);
    return frusta_.hold(center, 0.5f * glm::length(cell.max - cell.min));
  }

  // The cell's screen rectangle in the occlusion grid; none without occlusion, or for meshes that
  // neither hide nor are hidden.
  std::optional<CoverageGrid::Rect> occlusion_rect(const InstanceCell& cell) const {
    if (!occlusion_ || meshes_[tables_[cell.table].mesh].sample_positions.empty()) return std::nullopt;
    return rect_of(*occlusion_, cell);
  }

  // Opens the cell: its instances in view, large near ones by their parts in view.
  void open(const InstanceCell& cell) {
    const InstanceTable& table = tables_[cell.table];
    const SampledMesh& mesh = meshes_[table.mesh];
    OpenCell open;
    for (std::uint32_t i : cell.members) {
      const glm::mat4 m = table.transform(i);
      const float scale = uniform_scale(m);
      Candidate whole{cell.table, i, nullptr, glm::vec3(m * glm::vec4(mesh.center, 1.0f)), mesh.radius * scale,
                      mesh.area * scale * scale};
      if (!frusta_.hold(whole.center, whole.radius) || !shadows_receivers(mesh.center, mesh.half_size, m)) continue;
      if (!occlusion_ || !counted_by_parts(view_, *occlusion_, mesh, m, whole)) {
        whole.order = depth_order(view_, whole.center);
        open.candidates.push_back(whole);
        continue;
      }
      add_parts(whole, mesh, m, open.candidates);
    }
    if (open.candidates.empty()) return;
    std::sort(open.candidates.begin(), open.candidates.end(), before);
    open_.push_back(std::move(open));
    std::push_heap(open_.begin(), open_.end(), later);
  }

  // The parts of an instance that are in view, each with its depth order.
  void add_parts(const Candidate& whole, const SampledMesh& mesh, const glm::mat4& transform, std::vector<Candidate>& out) const {
    const float scale = uniform_scale(transform);
    for (const MeshPart& part : mesh.parts) {
      Candidate c{whole.table, whole.instance, &part, glm::vec3(transform * glm::vec4(part.center, 1.0f)), part.radius * scale,
                  part.area * scale * scale};
      if (!frusta_.hold(c.center, c.radius) || !shadows_receivers(part.center, part.half_size, transform)) continue;
      c.order = depth_order(view_, c.center);
      out.push_back(c);
    }
  }

  // A far cell whose instances need less than a point each on average, counted as one object
  // (the randomized z-buffer's aggregate): its expected points go one each to the first of its
  // members, in their fixed random order. False when the cell is not far enough. `rect` and
  // `transmittance` are the cell's in the occlusion grid.
  bool add_as_aggregate(const InstanceCell& cell, const std::optional<CoverageGrid::Rect>& rect, float transmittance) {
    const InstanceTable& table = tables_[cell.table];
    const SampledMesh& mesh = meshes_[table.mesh];
    // Instances that each stand for several (rounds_up) are already a far cell's aggregate.
    if (mesh.samples == 0 || table.rounds_up) return false;
    const glm::vec3 center = 0.5f * (cell.min + cell.max);
    const float radius = 0.5f * glm::length(cell.max - cell.min);
    if (!(radius < aggregate_radius * glm::distance(view_.eye, center))) return false;
    const Candidate all{cell.table, cell.members.front(), nullptr, center, radius, cell.area};
    float needed = unoccluded_count(view_, coverage_ ? &*coverage_ : nullptr, all, mesh, table.transform(cell.members.front()));
    if (!(needed < static_cast<float>(cell.members.size()))) return false;
    needed *= visible_share(transmittance, view_.full_count_transmittance);
    const std::uint64_t seed = table.seeds.size() > cell.members.front() ? table.seeds[cell.members.front()] : cell.members.front();
    const auto count = static_cast<std::size_t>(std::floor(needed + Random(derive_seed(seed, 0x61676772u)).uniform()));
    for (std::size_t i = 0; i < std::min(count, cell.members.size()); ++i) {
      const std::uint32_t instance = cell.members[i];
      const std::uint64_t instance_seed = table.seeds.size() > instance ? table.seeds[instance] : instance;
      const std::uint32_t first = Random(derive_seed(instance_seed, 0x6f6e65u)).below(static_cast<std::uint32_t>(mesh.samples));
      frame_.points.push_back({cell.table, instance, 1, first});
      ++frame_.point_count;
      if (rect) occlusion_->cover(std::span(mesh.sample_positions).subspan(first, 1), table.transform(instance));
    }
    return true;
  }

  // Adds the nearest candidate of the open cells.
  void add_next() {
    std::pop_heap(open_.begin(), open_.end(), later);
    OpenCell& cell = open_.back();
    const Candidate c = cell.candidates[cell.next++];
    if (cell.next == cell.candidates.size()) {
      open_.pop_back();
    } else {
      std::push_heap(open_.begin(), open_.end(), later);
    }
    add(c);
  }

  // An instance's or part's rectangle in the occlusion grid and its count with what is already
  // covered in front; none when it is hidden or off screen.
  struct Counted {
    std::optional<CoverageGrid::Rect> rect;  // none without occlusion or for meshes that never hide
    float transmittance = 1.0f;
    float needed = 0.0f;
  };
  std::optional<Counted> count(const Candidate& c, const SampledMesh& mesh, const glm::mat4& transform) const {
    Counted counted;
    // Only point meshes hide others and are hidden: ground and buildings are large and far from
    // their bounds.
    if (occlusion_ && !mesh.sample_positions.empty()) counted.rect = rect_of(*occlusion_, c, mesh, transform);
    if (counted.rect) {
      if (!counted.rect->on_screen()) return std::nullopt;  // its sphere reached into the view, its box does not
      counted.transmittance = occlusion_->transmittance(*counted.rect);
      if (counted.transmittance < hidden_transmittance) return std::nullopt;
    }
    counted.needed = unoccluded_count(view_, coverage_ ? &*coverage_ : nullptr, c, mesh, transform) *
                     visible_share(counted.transmittance, view_.full_count_transmittance);
    return counted;
  }

  // The points a mostly hidden instance needs counted part by part, each by its own rectangle's
  // transmittance; infinity when a part needs more than its list holds.
  float needed_by_parts(const std::vector<Candidate>& parts, const SampledMesh& mesh, const glm::mat4& transform) const {
    float total = 0.0f;
    for (const Candidate& part : parts) {
      const std::optional<Counted> counted = count(part, mesh, transform);
      if (!counted) continue;
      if (counted->needed > static_cast<float>(part.part->samples)) return INFINITY;
      total += counted->needed;
    }
    return total;
  }

  // An instance's parts in view, front to back.
  std::vector<Candidate> sorted_parts(const Candidate& whole, const SampledMesh& mesh, const glm::mat4& transform) const {
    std::vector<Candidate> parts;
    add_parts(whole, mesh, transform, parts);
    std::sort(parts.begin(), parts.end(), before);
    return parts;
  }

  // Counts one instance or part, chooses points or polygons, and covers what it hides. A part's
  // count is scaled by `thinning` (in the band, over its instance's polygons).
  void add(const Candidate& c, float thinning = 1.0f) {
    const SampledMesh& mesh = meshes_[tables_[c.table].mesh];
    const glm::mat4 transform = tables_[c.table].transform(c.instance);
    const std::optional<Counted> counted = count(c, mesh, transform);
    if (!counted) return;
    const std::optional<CoverageGrid::Rect>& rect = counted->rect;
    const float needed = counted->needed;
    const std::uint32_t first = c.part ? c.part->first : 0;
    const std::size_t samples = c.part ? c.part->samples : mesh.samples;
    const float ratio = needed / polygon_equivalent(view_, mesh);
    const bool as_polygons = !c.part && (ratio > band_low || needed > static_cast<float>(samples));
    const bool large = !c.part && rect && occlusion_->cells_in(*rect) > pixels_to_split && !mesh.parts.empty();
    if (large && !as_polygons && needed >= static_cast<float>(mesh.parts.size())) {
      // Left whole in case it needed polygons, it needs points after all now that so much of it
      // is hidden: counted by parts, front to back, so that its points go where it can be seen.
      for (const Candidate& part : sorted_parts(c, mesh, transform)) add(part);
      return;
    }
    if (large && as_polygons && counts_follow_visible_share() && ratio * counted->transmittance < band_high) {
      // Mostly hidden, where counts follow the visible share (a shadow map's view): counted by
      // parts, it may need fewer points than its polygons cost; the band as for whole instances.
      // (In the frame a part keeps its full count until nearly hidden, and the polygons of the
      // parts that show cost less.)
      const std::vector<Candidate> parts = sorted_parts(c, mesh, transform);
      const float parts_ratio = needed_by_parts(parts, mesh, transform) / polygon_equivalent(view_, mesh);
      if (parts_ratio < band_high) {
        for (const Candidate& part : parts) add(part, band_thinning(parts_ratio));
        if (parts_ratio > band_low) add_polygons(c, mesh, transform, *rect);
        return;
      }
    }
    const float drawn = (as_polygons ? band_thinning(ratio) : 1.0f) * thinning * needed;
    // Rounded up or down at the candidate's own fixed threshold: unbiased over many small
    // instances, and steady from frame to frame.
    const auto count = static_cast<std::uint32_t>(std::min(std::floor(drawn + rounding(tables_[c.table], c, mesh)),
                                                           static_cast<float>(samples)));
    const bool as_points = (c.part || ratio < band_high) && samples > 0;
    if (as_points && count > 0) {
      frame_.points.push_back({c.table, c.instance, count, first});
      frame_.point_count += count;
    }
    if (as_polygons) {
      add_polygons(c, mesh, transform, rect);
    } else if (rect) {
      cover(*occlusion_, mesh, first, transform, *rect, as_points ? count : 0);
    }
  }

  bool counts_follow_visible_share() const { return view_.full_count_transmittance >= 1.0f; }

  // The share of its count an instance keeps as points at `ratio` of its polygons' cost: all below
  // the band, none above, thinning out over its polygons in between.
  static float band_thinning(float ratio) { return std::clamp((band_high - ratio) / (band_high - band_low), 0.0f, 1.0f); }

  // Draws the instance as polygons, and covers what they hide. A large one (over pixels_to_split)
  // draws those of its parts that nearer objects leave to be seen; for a small one the parts'
  // tests and draw calls cost more than the triangles they could skip.
  void add_polygons(const Candidate& c, const SampledMesh& mesh, const glm::mat4& transform, const std::optional<CoverageGrid::Rect>& rect) {
    std::uint64_t drawn = ~std::uint64_t{0};
    std::size_t triangles = mesh.triangles;
    if (rect && !mesh.polygon_parts.empty() && occlusion_->cells_in(*rect) > pixels_to_split) {
      drawn = 0;
      triangles = 0;
      for (std::size_t i = 0; i < mesh.polygon_parts.size(); ++i) {
        const PolygonPart& part = mesh.polygon_parts[i];
        const std::optional<CoverageGrid::Rect> part_rect = occlusion_->project(part.center, part.half_size, transform);
        if (part_rect && (!part_rect->on_screen() || occlusion_->transmittance(*part_rect) < hidden_transmittance)) continue;
        drawn |= std::uint64_t{1} << i;
        triangles += part.index_count / 3;
      }
      if (drawn == 0) return;
    }
    frame_.polygons[c.table].push_back(c.instance);
    frame_.polygon_parts[c.table].push_back(drawn);
    frame_.triangle_count += triangles;
    if (rect) cover_polygons(*occlusion_, mesh, transform, *rect);
  }

  const SamplerView& view_;
  const TableList& tables_;
  const std::vector<SampledMesh>& meshes_;
  ViewFrusta frusta_;
  std::optional<CoverageGrid> coverage_;
  CoverageGrid* occlusion_ = nullptr;
  std::vector<OpenCell> open_;  // a heap (later)
  SampledFrame frame_;
};

}  // namespace

SampledFrame sample_view(const SamplerView& view, const TableList& tables, const std::vector<SampledMesh>& meshes,
                         const InstanceCells& cells) {
  return ViewSampling(view, tables, meshes).run(cells);
}

SampledFrame sample_view(const SamplerView& view, const TableList& tables, const std::vector<SampledMesh>& meshes) {
  return sample_view(view, tables, meshes, InstanceCells(tables, meshes));
}

}  // namespace pointgen
