#pragma once
#include "app/clock.hpp"
#include "app/gl/glfw_window.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/camera_path.hpp"
#include "app/view/flight_camera.hpp"
#include "app/view/hud.hpp"

#include <optional>
#include <string>
#include <vector>

namespace ecoview {

// The frame loop of ecoview view: input, camera (flight, orbit or a path playing), the renderer,
// the HUD, path recording and written frames.
class Viewer {
 public:
  struct Settings {
    RenderSettings render;
    shadow::Light light;
    double fps = 0.0;  // 0: scene time is the clock's; otherwise frame i is at time i / fps
    std::string scene_line;
    std::optional<CameraPath> play;
    std::string record_file;
    std::string out;  // folder of P's frames
    std::string screenshot;  // file the last frame's window goes to, if any
    bool hud = true;
    bool full_hud = false;  // the HUD's panel unfolded
    bool shadow_map_inset = false;
    bool aliasing_overlay = false;
  };
  Viewer(const Scene& scene, Settings settings, GlfwWindow& window);

  // One frame, from input to swap. The last one (`last`, or the one in which Esc closes the window)
  // writes the window as shown to the screenshot file, if there is one.
  void frame(bool last);
  // Writes the path being recorded, if any.
  void finish();
  // Frames shown, their median time, and where the camera is.
  std::string summary() const;

 private:
  // Scene time: seconds since the start (or since recording started), or frames / fps.
  double scene_time(Clock::time_point now) const;
  void handle_keys();
  void toggle_full_panel();
  FlightInput flight_input();
  shadow::Camera place_camera(double t, double seconds);
  void toggle_orbit();
  void toggle_recording();
  void write_capture_frame();
  void write_window(const std::string& file) const;
  void apply_controls();
  ViewStatus status() const;
  // Whether the HUD is shown and a field or slider of it has the keyboard or the mouse.
  bool hud_takes_keyboard() const;
  bool hud_takes_mouse() const;

  const Scene& scene_;
  Settings settings_;
  GlfwWindow& window_;
  Renderer renderer_;
  Hud hud_;
  ViewControls controls_;
  FlightCamera flight_;
  shadow::Camera camera_;
  bool following_path_;
  bool hud_shown_;
  int frame_ = 0;
  // Scene time starts at origin_ (origin_frame_ with --fps); recording moves it to its first frame.
  Clock::time_point origin_;
  int origin_frame_ = 0;
  bool restart_time_ = false;
  Clock::time_point last_frame_start_;  // flight moves by the clock's time, whatever --fps says
  glm::dvec2 last_cursor_{0.0};
  bool recording_ = false;
  std::vector<CameraPath::Key> recorded_;
  bool write_frame_ = false;  // P: write this frame once it is drawn
  std::vector<double> frame_ms_;
  std::string activity_;
};

}  // namespace ecoview
