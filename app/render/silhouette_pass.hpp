#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/adjacency_draw.hpp"
#include "app/render/gpu_scene.hpp"
#include "shadow/light.hpp"
#include "shadow/shadow_setup.hpp"

namespace ecoview {

// The silhouette map of a shadow map (Sen, Cammarano and Hanrahan 2003): a grid as fine as the
// depth map's, shifted half a texel so that each cell's corners are four depth samples, holding
// per cell a point where a silhouette edge of the polygon casters, as the light sees them, crosses
// it (the one nearest the light where several do); -1 where none does. The
// frame's lighting rebuilds the shadow's edge from these points (shaders/lighting.glsl), or, for
// hybrid shadows, finds the pixels a caster's edge may shadow (a shadow thinner than a texel). Point
// splats have no edges: their shadows are the depth map's alone.
class SilhouettePass {
 public:
  explicit SilhouettePass(int size);
  // The layer of view `layer` of `setup`, as the depth map has it; a paraboloid view gets none
  // (edges are curves in its map). The casters are `scene`, with its neighbours found
  // (GpuScene::add_adjacency), and `plants`, if any: the plants the GPU sampler chose as polygons.
  void render(const GpuScene& scene, const GpuScene::PlantDraws* plants, const shadow::ShadowSetup& setup, int layer,
              const shadow::Light& light);
  GLuint points() const { return points_.name(); }  // RG16F, a position in the cell (0..1 each way)
  // Per cell, the window depth of the edge whose point it holds (1 where none), one layer a view.
  GLuint edge_depths() const { return depths_.name(); }

 private:
  void allocate(int layers);

  int size_;
  int layers_ = 0;
  gl::Texture points_{GL_TEXTURE_2D_ARRAY};
  gl::Texture depths_{GL_TEXTURE_2D_ARRAY};  // the edges' depths, to keep the nearest
  gl::Framebuffer framebuffer_;
  AdjacencyDraw edges_;
};

}  // namespace ecoview
