#include "app/view/hud.hpp"

#include "app/capture/aliasing_colours.hpp"
#include "app/errors.hpp"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <array>
#include <cstdio>

namespace ecoview {
namespace {

const std::array<int, 4> shadow_sizes = {512, 1024, 2048, 4096};
constexpr float inset_pixels = 256.0f;

ImTextureID imgui_texture(GLuint texture) { return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture)); }

std::string millions(std::size_t n) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f M", static_cast<double>(n) * 1e-6);
  return text;
}

// Light direction as azimuth (degrees from +Z towards +X) and elevation of the way to the light.
void edit_direction(glm::vec3& direction) {
  const glm::vec3 to_light = -glm::normalize(direction);
  float azimuth = glm::degrees(std::atan2(to_light.x, to_light.z));
  float elevation = glm::degrees(std::asin(glm::clamp(to_light.y, -1.0f, 1.0f)));
  const bool turned = ImGui::SliderFloat("light azimuth", &azimuth, -180.0f, 180.0f, "%.0f deg");
  const bool raised = ImGui::SliderFloat("light elevation", &elevation, -89.0f, 89.0f, "%.0f deg");
  if (turned || raised) {
    const float a = glm::radians(azimuth), e = glm::radians(elevation);
    direction = -glm::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
  }
}

// The heat map as RGBA, transparent where it is black (no surface or no shadow map).
std::vector<std::uint8_t> translucent(const Image8& heat_map, std::uint8_t alpha) {
  std::vector<std::uint8_t> rgba;
  rgba.reserve(heat_map.samples.size() / 3 * 4);
  for (std::size_t p = 0; p < heat_map.samples.size(); p += 3) {
    const std::uint8_t r = heat_map.samples[p], g = heat_map.samples[p + 1], b = heat_map.samples[p + 2];
    rgba.insert(rgba.end(), {r, g, b, r == 0 && g == 0 && b == 0 ? std::uint8_t{0} : alpha});
  }
  return rgba;
}

// Whether the method looks its shadows up in a map the inset and the overlay can show.
bool has_map(const Renderer& renderer) {
  return shadow::technique(renderer.settings().method).lookup == shadow::Lookup::map &&
         renderer.shadow_setup().selection != shadow::ViewSelection::screen_mask;
}

// Whether the frame's shadows come from a map, paged or not, made at the settings' size: not
// without shadows, nor from shadow volumes' screen mask.
bool uses_shadow_size(const Renderer& renderer) {
  return shadow::technique(renderer.settings().method).lookup != shadow::Lookup::none &&
         renderer.shadow_setup().selection != shadow::ViewSelection::screen_mask;
}

}  // namespace

Hud::Hud(GlfwWindow& window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
  ImGui::StyleColorsDark();
  const bool window_ok = ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);
  if (!window_ok || !ImGui_ImplOpenGL3_Init("#version 450 core")) {
    if (window_ok) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    throw RuntimeFailure("the HUD (Dear ImGui) cannot use this window's OpenGL context");
  }
}

Hud::~Hud() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

bool Hud::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }
bool Hud::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }

void Hud::draw(const ViewStatus& status, const Renderer& renderer, ViewControls& controls) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  if (controls.aliasing_overlay && has_map(renderer)) draw_aliasing_overlay(renderer);
  draw_panel(status, renderer, controls);
  if (controls.shadow_map_inset && has_map(renderer)) draw_shadow_map_inset(renderer);
  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

// Folded, the panel is the summary alone and lets the mouse through to fly the camera.
void Hud::draw_panel(const ViewStatus& status, const Renderer& renderer, ViewControls& controls) {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize;
  if (!controls.full_panel) flags |= ImGuiWindowFlags_NoInputs;
  ImGui::Begin("ecoview", nullptr, flags);
  draw_summary(status, renderer, !controls.full_panel);
  if (controls.full_panel) {
    draw_details(status, renderer);
    ImGui::Separator();
    draw_controls(renderer, controls);
    ImGui::Separator();
    ImGui::TextDisabled("WASD move, Q/E down/up, drag to look, wheel or +/- speed, O orbit,");
    ImGui::TextDisabled("R record path, P write frame, Tab fold this, H hide all, Esc quit");
  }
  ImGui::End();
}

// What a glance needs: the frame rate, the method and its map, the geometry drawn, and what the
// viewer is doing (recording, playing, a file written or an error).
void Hud::draw_summary(const ViewStatus& status, const Renderer& renderer, bool folded) {
  const RenderSettings& settings = renderer.settings();
  const FrameStats& s = renderer.stats();
  const std::string map = uses_shadow_size(renderer) ? ", map " + std::to_string(settings.shadow_size) : "";
  ImGui::Text("frame %.0f ms (%.1f fps), %s%s", status.frame_ms, status.frame_ms > 0.0 ? 1000.0 / status.frame_ms : 0.0,
              shadow::technique(settings.method).name.c_str(), map.c_str());
  ImGui::Text("points %s, triangles %s", millions(s.points).c_str(), millions(s.triangles).c_str());
  if (folded) {
    ImGui::SameLine();
    ImGui::TextDisabled("(Tab: more)");
  }
  if (!status.activity.empty()) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", status.activity.c_str());
}

void Hud::draw_details(const ViewStatus& status, const Renderer& renderer) {
  const FrameStats& s = renderer.stats();
  ImGui::Text("shadow pass %.0f ms (points %s), frame pass %.0f ms, sampling %.0f ms, host %.0f ms", s.shadow_pass_ms,
              millions(s.shadow_points).c_str(), s.frame_pass_ms, s.sample_ms, s.host_ms);
  // A fixed wrap width: wrapping at the window's own in an auto-sized window takes frames to settle.
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 34.0f);
  ImGui::TextUnformatted(status.scene.c_str());
  ImGui::PopTextWrapPos();
  ImGui::Text("camera (%.1f, %.1f, %.1f), %s, speed %.1f m/s", status.position.x, status.position.y, status.position.z,
              status.orbiting ? "orbit" : "flight", status.speed);
}

void Hud::draw_controls(const Renderer& renderer, ViewControls& controls) {
  if (ImGui::BeginCombo("method", shadow::technique(controls.method).name.c_str())) {
    for (const shadow::Technique& t : shadow::techniques()) {
      if (ImGui::Selectable(t.name.c_str(), t.method == controls.method)) controls.method = t.method;
    }
    ImGui::EndCombo();
  }
  if (ImGui::BeginCombo("shadow map", std::to_string(controls.shadow_size).c_str())) {
    for (int size : shadow_sizes) {
      if (ImGui::Selectable(std::to_string(size).c_str(), size == controls.shadow_size)) controls.shadow_size = size;
    }
    ImGui::EndCombo();
  }
  ImGui::SliderFloat("k (points per pixel)", &controls.k, 0.25f, 6.0f, "%.2f");
  if (controls.light.type != shadow::LightType::point) edit_direction(controls.light.direction);
  if (controls.light.type != shadow::LightType::directional) ImGui::DragFloat3("light position", &controls.light.position.x, 0.5f);
  ImGui::Checkbox("shadow map inset", &controls.shadow_map_inset);
  ImGui::SameLine();
  ImGui::Checkbox("aliasing overlay", &controls.aliasing_overlay);
  if (shadow::technique(renderer.settings().method).lookup != shadow::Lookup::none) ImGui::TextDisabled("%s", renderer.shadow_setup().description.c_str());
}

// A view of the map's first layer, read as plain depth (no comparison) shown in gray: no copy.
// Made again each frame, as the pass makes a new map when a setup needs more layers.
void Hud::draw_shadow_map_inset(const Renderer& renderer) {
  shadow_map_layer_ = gl::TextureView();
  const GLuint view = shadow_map_layer_.name();
  glTextureView(view, GL_TEXTURE_2D, renderer.shadow_map().depth_texture(), renderer.shadow_map().depth_format(), 0, 1, 0, 1);
  glTextureParameteri(view, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glTextureParameteri(view, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(view, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  const GLint gray[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};
  glTextureParameteriv(view, GL_TEXTURE_SWIZZLE_RGBA, gray);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - inset_pixels - 24.0f, 8.0f), ImGuiCond_FirstUseEver);
  ImGui::Begin("shadow map (first view)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  // GL's rows go up from the bottom: the map's top row at the top.
  ImGui::Image(imgui_texture(view), ImVec2(inset_pixels, inset_pixels), ImVec2(0, 1), ImVec2(1, 0));
  ImGui::End();
}

void Hud::draw_aliasing_overlay(const Renderer& renderer) {
  const Image8 heat = aliasing_heat_map(renderer.frame().read_aliasing());
  if (overlay_size_ != glm::ivec2(heat.width, heat.height)) {
    overlay_ = gl::Texture(GL_TEXTURE_2D);
    glTextureStorage2D(overlay_.name(), 1, GL_RGBA8, heat.width, heat.height);
    glTextureParameteri(overlay_.name(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    overlay_size_ = {heat.width, heat.height};
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(overlay_.name(), 0, 0, 0, heat.width, heat.height, GL_RGBA, GL_UNSIGNED_BYTE, translucent(heat, 160).data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  ImGui::GetBackgroundDrawList()->AddImage(imgui_texture(overlay_.name()), ImVec2(0, 0), ImGui::GetIO().DisplaySize);
}

}  // namespace ecoview
