#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/gpu_sampler.hpp"
#include "app/render/gpu_scene.hpp"
#include "app/render/image.hpp"
#include "app/render/point_splat.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"
#include "shadow/shadow_setup.hpp"
#include "shadow/virtual_map.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ecoview {

// Renders the camera's view in two steps (deferred shading): first the nearest surface of each
// pixel, polygons and point splats depth-tested together, into normal, albedo and linear view
// depth (the points into targets of their own, shaders/frame_surface.glsl); then Blinn-Phong
// lighting once per pixel, at the point of that depth on the ray through the pixel's centre, into
// sRGB colour, light visibility (the `shadow` AOV) and the shadow map's aliasing factor.
class FramePass {
 public:
  // `aliasing`: also fill the aliasing target (it costs shading time; otherwise it holds 0).
  // `surface_textures`: the scene has textures or alpha masks (GpuScene::has_surface_textures).
  FramePass(int width, int height, bool aliasing, bool surface_textures);

  // Clears the frame and draws the polygons' surfaces.
  void draw_surfaces(const GpuScene& scene, const shadow::Camera& camera) const;
  // Adds the surfaces of the plants a band of the GPU sampler chose as polygons.
  void add_chosen_surfaces(const GpuScene& scene, const GpuSampler& sampler, int band, const shadow::Camera& camera) const;
  // Adds the nearest splatted point of each pixel, depth-tested against the polygons, covering the
  // share of the pixel the points cover there (PointSplat::add); shading blends the polygons
  // behind into the rest.
  void add_points(const PointSplat& points, const shadow::Camera& camera) const;

  // `shadow_map`: the depth-texture array with one layer per view of `setup`, or for
  // ViewSelection::screen_mask a frame-sized mask (1 where lit); without one every surface facing
  // the light is lit.
  struct ShadowLookup {
    GLuint texture;
    const shadow::ShadowSetup& setup;
    int size;
    // For hybrid shadows, the lookup widened to mark where the map may be wrong, as a `shadow` AOV
    // neither 0 nor 1, so that the shadow volumes decide there (ShadowVolumePass::render_near_edges).
    bool marks_edges = false;
    // For hybrid shadows with point casters, their splats in layers of their own, after the views'.
    bool point_layers = false;
    // For shadow silhouette maps, the map's silhouette points (SilhouettePass), one layer a view;
    // 0 for none.
    GLuint silhouettes = 0;
    GLuint silhouette_depths = 0;  // and the depths of their edges (SilhouettePass::edge_depths)
    // For a virtual paged map (--method adaptive), its page table (PagedMap): `texture` holds the
    // pages, one a layer, each `size` texels a side with its guard; 0 for none.
    GLuint page_table = 0;
    shadow::VirtualMap pages{};
    std::vector<glm::ivec2> page_windows{};  // where each view's level's window starts
  };
  // Lights the surfaces drawn.
  void shade(const shadow::Camera& camera, const shadow::Light& light, const std::optional<ShadowLookup>& shadow_map) const;

  // --method auto's prediction: for each setup (its maps of `map_size` texels), the percentile
  // `fraction` of its aliasing factor for `camera` over the surfaces this frame holds that face the
  // light, on a grid of about 10,000 of its pixels; `surface_camera` is the camera they were drawn
  // with. On the GPU (shaders/predicted_aliasing.comp), read back as one histogram a setup of 256
  // bins an octave: within 0.3 % of the value.
  std::vector<float> predict_aliasing(const shadow::Camera& surface_camera, const shadow::Camera& camera, const shadow::Light& light,
                                      const std::vector<shadow::ShadowSetup>& setups, int map_size, float fraction) const;

  // The pages of the virtual map `pages` (its page table not yet filled) that the lighting will look up for
  // the frame's surfaces, appended once each as page numbers (shadow::VirtualMap::id) to the list
  // bound at storage binding 28 (a count, then the numbers), flagged in the array at binding 27,
  // which starts at zero (shaders/page_requests.comp).
  void request_pages(const shadow::Camera& camera, const shadow::Light& light, const ShadowLookup& pages) const;

  Image8 read_color() const;
  Image8 read_visibility() const;
  GLuint visibility_texture() const { return visibility_.name(); }  // R8, as read_visibility reads it
  // Linear view depth in metres; negative where no surface was drawn.
  Image<float> read_depth() const;
  // The nearest of those depths, found by the shading pass and read back (4 bytes); 0 where none.
  float nearest_depth() const;
  // The aliasing factor (docs/figures.md) of the surface in each pixel; negative where no surface was
  // drawn, 0 without a shadow map.
  Image<float> read_aliasing() const;
  // Binds the frame's surfaces and what finds their positions (frame_surface.glsl,
  // surface_position.glsl) for another pass's program; `camera` is the one they were drawn with.
  void bind_surfaces_for(const gl::Program& program, const shadow::Camera& camera) const;
  // The depth-stencil texture (GL_DEPTH32F_STENCIL8) the frame draws into.
  GLuint depth_stencil_texture() const { return depth_buffer_.name(); }
  // Whether to fill the aliasing target from the next frame on.
  void set_aliasing(bool wanted) { aliasing_wanted_ = wanted; }
  // Copies the colour to the default framebuffer (a window), scaled to fit.
  void present(int width, int height) const;


 private:
  template <class Sample>
  Image<Sample> read(const gl::Framebuffer& framebuffer, GLenum attachment, int channels, GLenum format, GLenum type) const;
  // What the shading program is built for: whether there are shadows, how a point picks its view
  // (shadow::ViewSelection), whether any view is a paraboloid's, and whether to fill the aliasing
  // target (shaders/lighting.glsl).
  struct ShadeVariant {
    bool shadows = false;
    int selection = 0;
    bool paraboloid = false;
    bool aliasing = false;
    bool marks_edges = false;
    bool point_layers = false;
    bool silhouettes = false;
    bool pages = false;
    auto operator<=>(const ShadeVariant&) const = default;
  };
  ShadeVariant shade_variant(const std::optional<ShadowLookup>& shadow_map) const;
  static std::string defines(const ShadeVariant& variant);
  // Built when a frame first needs it, then kept.
  const gl::Program& shade_program(const ShadeVariant& variant) const;
  const gl::Program& prediction_program(const ShadeVariant& variant) const;
  // The uniforms of lighting.glsl and surface_position.glsl: `surface_camera` reconstructs the
  // surfaces' positions, `camera` is the one they are seen and shaded for.
  void set_lighting(const gl::Program& program, const shadow::Camera& surface_camera, const shadow::Camera& camera,
                    const shadow::Light& light, const std::optional<ShadowLookup>& shadow_map) const;
  glm::mat4 view_projection(const shadow::Camera& camera) const;  // world to clip
  // The uniforms by which surface_position.glsl finds a surface drawn with `surface_camera`.
  void set_surface_camera(const gl::Program& program, const shadow::Camera& surface_camera) const;
  void set_camera(const gl::Program& program, const shadow::Camera& camera) const;
  // Binds the surfaces' targets and a program for polygons.
  void start_surfaces(const gl::Program& program, const shadow::Camera& camera) const;
  void set_light(const gl::Program& program, const shadow::Light& light, const std::optional<ShadowLookup>& shadow_map) const;
  void draw_fullscreen() const;  // one triangle over the viewport

  int width_, height_;
  bool aliasing_wanted_;
  // The surfaces: written by draw_surfaces and add_points.
  gl::Texture normals_{GL_TEXTURE_2D};
  gl::Texture albedos_{GL_TEXTURE_2D};
  gl::Texture depth_{GL_TEXTURE_2D};
  gl::Texture depth_buffer_{GL_TEXTURE_2D};
  gl::Framebuffer surfaces_;
  // The points' surfaces where they lie in front of the polygons (add_points), apart from the
  // polygons' (shaders/frame_surface.glsl), made when first needed; whether this frame added any.
  struct Surfaces {
    gl::Texture normals{GL_TEXTURE_2D}, albedos{GL_TEXTURE_2D}, depth{GL_TEXTURE_2D};
    gl::Framebuffer framebuffer;  // the three, and the frame's depth buffer
  };
  mutable std::unique_ptr<Surfaces> point_surfaces_;
  mutable bool points_added_ = false;
  // Binds both surfaces for a program that includes frame_surface.glsl.
  void bind_surfaces(const gl::Program& program) const;
  // Their lighting: written by shade as images, read back and blitted through lit_.
  gl::Texture color_{GL_TEXTURE_2D};
  gl::Texture visibility_{GL_TEXTURE_2D};
  gl::Texture aliasing_{GL_TEXTURE_2D};
  gl::Framebuffer lit_;
  gl::Program surface_program_;
  gl::Program plant_surface_program_;  // for the GPU sampler's polygon plants (shaders/instance.glsl)
  gl::Program point_program_;
  mutable std::map<ShadeVariant, gl::Program> shade_programs_, prediction_programs_, request_programs_;
  gl::Buffer histograms_;  // predict_aliasing's
  gl::VertexArray empty_vertex_array_;  // for the fullscreen triangle, which has no attributes
  gl::Buffer nearest_;
};

}  // namespace ecoview
