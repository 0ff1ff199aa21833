#include "app/view/hud.hpp"

#include "app/capture/aov.hpp"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <array>
#include <cstdio>

namespace ecoview {
namespace {

const std::array<ShadowMethod, 10> methods = {ShadowMethod::uniform, ShadowMethod::psm,     ShadowMethod::lispsm,
                                               ShadowMethod::cascades, ShadowMethod::dpsm,  ShadowMethod::ipsm,
                                               ShadowMethod::volumes, ShadowMethod::reference, ShadowMethod::automatic,
                                               ShadowMethod::none};
const std::array<int, 4> shadow_sizes = {512, 1024, 2048, 4096};
constexpr float inset_pixels = 256.0f;

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

}  // namespace

void Hud::ImageTexture::upload(const Image8& image, std::uint8_t alpha, bool black_clear) {
  if (image.width != width || image.height != height) {
    texture = gl::Texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.name(), 1, GL_RGBA8, image.width, image.height);
    glTextureParameteri(texture.name(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    width = image.width;
    height = image.height;
  }
  std::vector<std::uint8_t> rgba;
  rgba.reserve(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t p = 0; p < static_cast<std::size_t>(width) * height; ++p) {
    bool black = true;
    for (int c = 0; c < 3; ++c) {
      const std::uint8_t v = image.samples[p * image.channels + (image.channels == 1 ? 0 : c)];
      black = black && v == 0;
      rgba.push_back(v);
    }
    rgba.push_back(black && black_clear ? 0 : alpha);
  }
  glTextureSubImage2D(texture.name(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

Hud::Hud(const GlfwWindow& window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);  // chains to the window's own callbacks
  ImGui_ImplOpenGL3_Init("#version 450 core");
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
  if (controls.aliasing_overlay) draw_aliasing_overlay(renderer);
  draw_panel(status, renderer, controls);
  if (controls.shadow_map_inset && renderer.settings().method != ShadowMethod::none &&
      renderer.shadow_setup().selection != shadow::ViewSelection::screen_mask) {
    draw_shadow_map_inset(renderer);
  }
  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Hud::draw_panel(const ViewStatus& status, const Renderer& renderer, ViewControls& controls) {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("ecoview", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  const FrameStats& s = renderer.stats();
  ImGui::Text("frame %.0f ms (%.1f fps)", status.frame_ms, status.frame_ms > 0.0 ? 1000.0 / status.frame_ms : 0.0);
  ImGui::Text("shadow pass %.0f ms, frame pass %.0f ms, sampling %.0f ms", s.shadow_pass_ms, s.frame_pass_ms, s.sample_ms);
  ImGui::Text("points %s, triangles %s, shadow points %s", millions(s.points).c_str(), millions(s.triangles).c_str(),
              millions(s.shadow_points).c_str());
  ImGui::TextWrapped("%s", status.scene.c_str());
  ImGui::Text("camera (%.1f, %.1f, %.1f), %s, speed %.1f m/s", status.position.x, status.position.y, status.position.z,
              status.orbiting ? "orbit" : "flight", status.speed);
  if (!status.activity.empty()) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", status.activity.c_str());
  ImGui::Separator();

  if (ImGui::BeginCombo("method", shadow_method_name(controls.method).c_str())) {
    for (ShadowMethod m : methods) {
      if (ImGui::Selectable(shadow_method_name(m).c_str(), m == controls.method)) controls.method = m;
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
  ImGui::TextDisabled("%s", renderer.shadow_setup().description.c_str());
  ImGui::Separator();
  ImGui::TextDisabled("WASD move, Q/E down/up, drag to look, wheel or +/- speed, O orbit,");
  ImGui::TextDisabled("R record path, P screenshot, H hide this, Esc quit");
  ImGui::End();
}

void Hud::draw_shadow_map_inset(const Renderer& renderer) {
  inset_.upload(depth_gray(renderer.shadow_map().read_layer(0)), 255, false);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - inset_pixels - 24.0f, 8.0f), ImGuiCond_FirstUseEver);
  ImGui::Begin("shadow map (first view)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(inset_.texture.name())), ImVec2(inset_pixels, inset_pixels));
  ImGui::End();
}

void Hud::draw_aliasing_overlay(const Renderer& renderer) {
  overlay_.upload(aliasing_heat_map(renderer.frame().read_aliasing()), 160, true);
  ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(overlay_.texture.name())),
                                           ImVec2(0, 0), ImGui::GetIO().DisplaySize);
}

}  // namespace ecoview
