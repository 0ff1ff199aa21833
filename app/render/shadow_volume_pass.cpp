#include "app/render/shadow_volume_pass.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"
#include "shadow/post_perspective.hpp"

namespace ecoview {
namespace {

// Pushes the volumes a few depth steps away from the eye, so that a triangle's near cap lies
// behind the triangle as the frame drew it (counted, so the triangle does not shadow itself)
// whatever the rounding of the two passes. No slope-scaled part: on volume faces seen at a grazing
// angle it moved shadow edges by a pixel (floating-box lines, docs/benchmarks.md).
constexpr float offset_factor = 0.0f;
constexpr float offset_units = 8.0f;

}  // namespace

ShadowVolumePass::ShadowVolumePass(int width, int height, GLuint depth_stencil, bool masked_casters)
    : width_(width),
      height_(height),
      volumes_({"world_position.vert", "shadow_volume.geom", "stencil_count.frag"}, gl::surface_defines(masked_casters)),
      mask_program_(gl::build_program({"fullscreen.vert", "light_mask.frag"})),
      edge_program_(gl::build_program({"fullscreen.vert", "edge_pixels.frag"})) {
  glTextureStorage2D(mask_.name(), 1, GL_R8, width, height);
  const GLuint fb = framebuffer_.name();
  glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT0, mask_.name(), 0);
  glNamedFramebufferTexture(fb, GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil, 0);
  glNamedFramebufferTexture(stencil_only_.name(), GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil, 0);
  glNamedFramebufferDrawBuffer(stencil_only_.name(), GL_NONE);
  if (glCheckNamedFramebufferStatus(fb, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE ||
      glCheckNamedFramebufferStatus(stencil_only_.name(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw RuntimeFailure("the shadow-volume targets are not supported by this driver; try another --backend");
  }
  if (masked_casters) masked_prisms_.emplace(std::vector<std::string>{"world_position.vert", "masked_prism.geom", "masked_prism.frag"}, gl::surface_defines(true));
}

void ShadowVolumePass::render(const MaskFrame& frame, Counting counting) {
  const GLuint fb = framebuffer_.name();
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glViewport(0, 0, width_, height_);
  const float unlit = 0.0f;
  const GLint zero = 0;
  glClearNamedFramebufferfv(fb, GL_COLOR, 0, &unlit);
  glClearNamedFramebufferiv(fb, GL_STENCIL, 0, &zero);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  count(frame, counting);
  // The mask: 1 where the count is 0.
  glStencilFunc(GL_EQUAL, 0, 0xFF);
  write_mask(1.0f);
  glDisable(GL_STENCIL_TEST);
  shadow_by_masked(frame);
}

void ShadowVolumePass::render_near_edges(const MaskFrame& frame, Counting counting) {
  constexpr GLuint edge_bit = 0x80, count_bits = 0x7F;
  const GLuint visibility = frame.frame.visibility_texture();
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);  // the AOV is a compute pass's image
  glCopyImageSubData(visibility, GL_TEXTURE_2D, 0, 0, 0, 0, mask_.name(), GL_TEXTURE_2D, 0, 0, 0, 0, width_, height_, 1);
  const GLint zero = 0;
  glClearNamedFramebufferiv(stencil_only_.name(), GL_STENCIL, 0, &zero);
  glBindFramebuffer(GL_FRAMEBUFFER, stencil_only_.name());
  glViewport(0, 0, width_, height_);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, edge_bit, edge_bit);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glUseProgram(edge_program_.name());
  glBindTextureUnit(0, visibility);
  draw_fullscreen();

  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.name());
  glStencilFunc(GL_EQUAL, edge_bit, edge_bit);
  glStencilMask(count_bits);
  count(frame, counting);
  glStencilMask(0xFF);
  // Near edges: 1 where the count is 0, 0 where it is not.
  glStencilFunc(GL_EQUAL, edge_bit, 0xFF);
  write_mask(1.0f);
  glStencilFunc(GL_LESS, edge_bit, 0xFF);  // edge_bit < stencil: marked, and a count
  write_mask(0.0f);
  glStencilFunc(GL_EQUAL, edge_bit, edge_bit);
  shadow_by_masked(frame);
  glDisable(GL_STENCIL_TEST);
}

// The volumes: no colour, no depth writes, both faces; far caps at infinity kept by depth clamp.
// The stencil test is the caller's.
void ShadowVolumePass::count(const MaskFrame& frame, Counting counting) {
  const bool z_fail = counting == Counting::z_fail;
  glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_CLAMP);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(offset_factor, offset_units);
  if (z_fail) {  // leaving a volume behind the surface (a back face failing the depth test) counts +1
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
  } else {  // entering a volume in front of the surface (a front face passing) counts +1
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  }
  volumes_.draw(frame.polygons, frame.plants ? &*frame.plants : nullptr, [&](const gl::Program& program) {
    gl::set_uniform(program, "view_projection", frame.view_projection);
    gl::set_uniform(program, "light", shadow::homogeneous(frame.light));
    gl::set_uniform(program, "far_caps", z_fail ? 1 : 0);
  });
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_CLAMP);
  glDepthMask(GL_TRUE);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// Each masked triangle's prism, its faces facing away from the eye: a convex volume's back faces
// cover each pixel whose ray passes through it once, wherever the eye stands. No depth test: the
// surface may lie anywhere along the ray inside the prism. The stencil test is the caller's.
void ShadowVolumePass::shadow_by_masked(const MaskFrame& frame) {
  if (!masked_prisms_ || frame.scene_bounds.empty()) return;
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glEnable(GL_DEPTH_CLAMP);
  // The box a little larger, so that rounding leaves no receiver on its face outside a prism.
  const glm::vec3 margin = 0.01f * (frame.scene_bounds.max - frame.scene_bounds.min) + 0.01f;
  masked_prisms_->draw(frame.polygons, frame.plants ? &*frame.plants : nullptr, [&](const gl::Program& program) {
    gl::set_uniform(program, "view_projection", frame.view_projection);
    gl::set_uniform(program, "scene_min", frame.scene_bounds.min - margin);
    gl::set_uniform(program, "scene_max", frame.scene_bounds.max + margin);
    gl::set_uniform(program, "light", shadow::homogeneous(frame.light));
    frame.frame.bind_surfaces_for(program, frame.camera);
  });
  glDisable(GL_DEPTH_CLAMP);
  glCullFace(GL_BACK);
  glDisable(GL_CULL_FACE);
}

void ShadowVolumePass::write_mask(float value) const {
  glDisable(GL_DEPTH_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glUseProgram(mask_program_.name());
  gl::set_uniform(mask_program_, "value", value);
  draw_fullscreen();
}

void ShadowVolumePass::draw_fullscreen() const {
  glBindVertexArray(empty_vertex_array_.name());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace ecoview
