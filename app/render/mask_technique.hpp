#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/reference/exact_visibility.hpp"
#include "app/render/frame_pass.hpp"
#include "app/render/gpu_scene.hpp"
#include "app/scene/scene.hpp"
#include "pointgen/sampling/instance_cells.hpp"
#include "shadow/box.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"
#include "shadow/techniques.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ecoview {

// What a mask technique sees of a frame. The frame pass holds the frame's surfaces, not yet lit,
// or for a technique with a map lit by it (its `shadow` AOV then says where the map may be
// wrong).
struct MaskFrame {
  const shadow::Camera& camera;
  float aspect;
  const shadow::Light& light;
  const glm::mat4& view_projection;
  const shadow::Box& scene_bounds;                      // every caster and receiver, in any pose
  const GpuScene& polygons;                             // the polygon casters, those out of view too
  // With the GPU sampler, the plants it chose as polygons for the frame (GpuScene::draw_chosen):
  // casters too, which `polygons` does not hold.
  std::optional<GpuScene::PlantDraws> plants;
  const pointgen::TableList& tables;                   // as posed for the frame
  const pointgen::InstanceCells& cells;                 // of tables
  const FramePass& frame;
};

// The GL side of a technique whose lookup is a per-pixel mask (shadow::Lookup::mask): after the
// frame's surfaces, the pixels the light reaches. Made by make_mask_technique.
class MaskTechnique {
 public:
  virtual ~MaskTechnique() = default;
  // The frame's lit pixels: R8 of the frame's size, 1 where the light reaches the surface.
  virtual GLuint render(const MaskFrame& frame) = 0;
  // How the last mask was made, for the HUD and --stats.
  virtual const std::string& description() const = 0;
  // The frame's GPU stage the mask's work is timed as.
  virtual const char* stage() const = 0;
  // Whether the casters are the polygons the GpuScene holds: a frame draws its plants as polygons
  // out of view too.
  virtual bool casts_from_frame_polygons() const = 0;
  // Whether the mask is made on the CPU: the wall clock times it, which a GPU timer would not.
  virtual bool made_on_cpu() const = 0;
};

// What the masks are made from.
struct MaskSources {
  const Scene& scene;
  GpuScene& polygons;  // its meshes' neighbours are found for the masks that need them
  const FramePass& frame;
  glm::ivec2 size;  // the frame's
  // The exact visibility, posed for the frame (built when first asked for).
  std::function<ExactVisibility&()> exact;
};

// The mask technique of `method`, the one place each is registered; nullptr for a method whose
// lookup is not a mask.
std::unique_ptr<MaskTechnique> make_mask_technique(shadow::Method method, const MaskSources& sources);

}  // namespace ecoview
