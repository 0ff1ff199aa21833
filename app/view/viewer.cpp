#include "app/view/viewer.hpp"

#include "app/bench/frame_timing.hpp"
#include "app/capture/aov.hpp"
#include "app/capture/png.hpp"
#include "app/errors.hpp"
#include "app/file_io.hpp"

#include <GLFW/glfw3.h>

#include <cstdio>

namespace ecoview {

Viewer::Viewer(const Scene& scene, Settings settings, GlfwWindow& window)
    : scene_(scene),
      settings_(std::move(settings)),
      window_(window),
      renderer_(scene, settings_.render),
      hud_(window),
      controls_{settings_.render.method, settings_.render.shadow_size, settings_.render.k, settings_.light,
                settings_.shadow_map_inset, settings_.aliasing_overlay, settings_.full_hud},
      flight_(scene.camera),
      camera_(scene.camera),
      following_path_(settings_.play.has_value()),
      hud_shown_(settings_.hud),
      origin_(Clock::now()),
      last_frame_start_(origin_),
      last_cursor_(window.cursor()) {}

double Viewer::scene_time(Clock::time_point now) const {
  if (settings_.fps > 0.0) return (frame_ - origin_frame_) / settings_.fps;
  return std::chrono::duration<double>(now - origin_).count();
}

void Viewer::frame(bool last) {
  const auto start = Clock::now();
  const double seconds = std::chrono::duration<double>(start - last_frame_start_).count();
  last_frame_start_ = start;
  handle_keys();
  apply_controls();
  if (restart_time_) {  // recording starts at t = 0
    origin_ = start;
    origin_frame_ = frame_;
    restart_time_ = false;
  }
  const double t = scene_time(start);
  camera_ = place_camera(t, seconds);
  if (recording_ && (recorded_.empty() || t > recorded_.back().t)) recorded_.push_back({t, camera_.position, camera_.target, camera_.up});

  renderer_.render(camera_, controls_.light, t);
  const glm::ivec2 size = window_.framebuffer_size();
  renderer_.frame().present(size.x, size.y);
  if (write_frame_) write_capture_frame();
  if (hud_shown_) hud_.draw(status(), renderer_, controls_);
  if (!settings_.screenshot.empty() && (last || window_.should_close())) write_window(settings_.screenshot);
  window_.swap_and_poll();
  frame_ms_.push_back(ms_since(start));
  ++frame_;
}

bool Viewer::hud_takes_keyboard() const { return hud_shown_ && hud_.wants_keyboard(); }
bool Viewer::hud_takes_mouse() const { return hud_shown_ && hud_.wants_mouse(); }

ViewStatus Viewer::status() const {
  ViewStatus s{frame_ms_.empty() ? 0.0 : frame_ms_.back(), settings_.scene_line, camera_.position, flight_.speed(),
               flight_.orbiting(), activity_};
  if (recording_) s.activity = "recording " + settings_.record_file + " (R stops)";
  if (following_path_) s.activity = "playing the camera path" + (activity_.empty() ? "" : "; " + activity_);
  return s;
}

// Keys pressed since the last frame; none while the HUD has the keyboard (a field or slider in use).
void Viewer::handle_keys() {
  if (!hud_takes_mouse()) flight_.scale_speed(static_cast<float>(window_.scrolled()));
  if (hud_takes_keyboard()) return;
  for (int key : window_.keys_pressed()) {
    switch (key) {
      case GLFW_KEY_ESCAPE: window_.close(); break;
      case GLFW_KEY_H: hud_shown_ = !hud_shown_; break;
      case GLFW_KEY_TAB: toggle_full_panel(); break;
      case GLFW_KEY_O: toggle_orbit(); break;
      case GLFW_KEY_R: toggle_recording(); break;
      case GLFW_KEY_P: write_frame_ = true; break;
      case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: flight_.scale_speed(1.0f); break;
      case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: flight_.scale_speed(-1.0f); break;
      default: break;
    }
  }
}

// Tab unfolds the panel, or folds it again; on a hidden HUD it shows the panel unfolded.
void Viewer::toggle_full_panel() {
  controls_.full_panel = !(hud_shown_ && controls_.full_panel);
  hud_shown_ = true;
}

FlightInput Viewer::flight_input() {
  FlightInput input;
  const glm::dvec2 cursor = window_.cursor();
  const bool dragging = window_.mouse_button_down(GLFW_MOUSE_BUTTON_LEFT) || window_.mouse_button_down(GLFW_MOUSE_BUTTON_RIGHT);
  if (dragging && !hud_takes_mouse()) input.look = glm::vec2(cursor - last_cursor_);
  last_cursor_ = cursor;
  if (hud_takes_keyboard()) return input;
  auto axis = [&](int plus, int minus) { return (window_.key_down(plus) ? 1.0f : 0.0f) - (window_.key_down(minus) ? 1.0f : 0.0f); };
  input.move = {axis(GLFW_KEY_D, GLFW_KEY_A), axis(GLFW_KEY_E, GLFW_KEY_Q), axis(GLFW_KEY_W, GLFW_KEY_S)};
  return input;
}

// The path's camera while it plays; after it, flight from where it ended.
shadow::Camera Viewer::place_camera(double t, double seconds) {
  const FlightInput input = flight_input();
  if (following_path_) {
    const shadow::Camera on_path = settings_.play->at(t, scene_.camera);
    if (t <= settings_.play->duration()) return on_path;
    following_path_ = false;
    activity_.clear();
    flight_.place(on_path);
  }
  flight_.update(input, seconds);
  return flight_.camera();
}

// Orbits around the surface in the middle of the last frame (or the point the camera looks at,
// where the middle shows sky).
void Viewer::toggle_orbit() {
  if (following_path_) {
    activity_ = "no orbit while a path plays";
    return;
  }
  if (flight_.orbiting()) {
    flight_.fly();
    return;
  }
  const Image<float> depth = renderer_.frame().read_depth();
  const float centre = depth.at(depth.width / 2, depth.height / 2);
  flight_.orbit(centre);
}

// Recording starts the scene's time at 0, so that capture --path replays moving objects with it.
void Viewer::toggle_recording() {
  if (following_path_) {
    activity_ = "no recording while a path plays";
    return;
  }
  if (!recording_) {
    recording_ = true;
    recorded_.clear();
    restart_time_ = true;
    return;
  }
  try {
    finish();
  } catch (const RuntimeFailure& e) {
    activity_ = e.what();  // the keys stay, for the next R or the exit to write
    recording_ = true;
  }
}

void Viewer::finish() {
  if (!recording_) return;
  recording_ = false;
  if (recorded_.empty()) return;
  write_file_atomically(settings_.record_file, CameraPath(recorded_).json());
  activity_ = "wrote " + std::to_string(recorded_.size()) + " keys to " + settings_.record_file;
}

// P: the frame as capture writes its color AOV, named by this frame's number.
void Viewer::write_capture_frame() {
  write_frame_ = false;
  const std::filesystem::path file = aov_file(settings_.out, Aov::color, frame_);
  try {
    write_file_atomically(file, encode_aov(Aov::color, renderer_, camera_.far));
    activity_ = "wrote " + file.string();
  } catch (const RuntimeFailure& e) {
    activity_ = e.what();
  }
}

void Viewer::write_window(const std::string& file) const {
  const glm::ivec2 size = window_.framebuffer_size();
  std::vector<std::uint8_t> bottom_up(static_cast<std::size_t>(size.x) * size.y * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size.x, size.y, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
  write_file_atomically(file, encode_png(from_bottom_up(size.x, size.y, 3, bottom_up)));
}

// The HUD's edits reach the renderer from this frame on.
void Viewer::apply_controls() {
  const RenderSettings& now = renderer_.settings();
  if (controls_.method != now.method || controls_.shadow_size != now.shadow_size || controls_.k != now.k) {
    try {
      renderer_.change(controls_.method, controls_.shadow_size, controls_.k);
    } catch (const InputError& e) {  // a map larger than this driver renders
      activity_ = e.what();
      controls_.method = now.method;
      controls_.shadow_size = now.shadow_size;
      controls_.k = now.k;
    }
  }
  renderer_.set_aliasing(controls_.aliasing_overlay);
}

std::string Viewer::summary() const {
  // The first frame holds the warm-up (the driver's shader compilation, the PSM's first depth).
  const double median_ms = median(std::vector<double>(frame_ms_.begin() + (frame_ms_.size() > 1 ? 1 : 0), frame_ms_.end()));
  char text[256];
  std::snprintf(text, sizeof text, "view: %d frames, median %.1f ms (%.1f fps); camera at (%.3f, %.3f, %.3f) looking at (%.3f, %.3f, %.3f)",
                frame_, median_ms, median_ms > 0.0 ? 1000.0 / median_ms : 0.0, camera_.position.x, camera_.position.y,
                camera_.position.z, camera_.target.x, camera_.target.y, camera_.target.z);
  return text;
}

}  // namespace ecoview
