#pragma once
#include "app/gl/glfw_window.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/camera_path.hpp"
#include "app/view/flight_camera.hpp"
#include "app/view/hud.hpp"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace ecoview {

// The frame loop of ecoview view: input, camera (flight, orbit or a path playing), the renderer,
// the HUD, path recording and screenshots.
class Viewer {
 public:
  struct Settings {
    RenderSettings render;
    double fps = 0.0;  // 0: the clock's time; otherwise frame i is at time i / fps
    std::string scene_line;
    shadow::Light light;
    std::optional<CameraPath> play;
    std::string record_file;
    std::string out;  // folder of P's frames
    bool hud = true;
    bool shadow_map_inset = false;
    bool aliasing_overlay = false;
  };
  Viewer(const Scene& scene, Settings settings, GlfwWindow& window);

  // One frame, from input to swap; with `screenshot`, the window as shown goes to that file.
  void frame(const std::string& screenshot = "");
  // Writes a path still being recorded.
  void finish();
  // Frames shown, their median time, and where the camera is.
  std::string summary() const;

 private:
  // Scene time at `now`: seconds since the start (or since recording started), or frames / fps.
  double scene_time(std::chrono::steady_clock::time_point now);
  void handle_keys();
  FlightInput flight_input();
  shadow::Camera place_camera(double t, double seconds);
  void toggle_recording();
  void write_capture_frame();
  void write_window(const std::string& file) const;
  void apply_controls();

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
  int origin_frame_ = 0;
  std::chrono::steady_clock::time_point origin_;
  bool restart_time_ = false;  // at the next frame, which is then at t = 0
  double last_time_ = 0.0;
  glm::dvec2 last_cursor_{0.0};
  bool recording_ = false;
  std::vector<CameraPath::Key> recorded_;
  std::vector<double> frame_ms_;
  std::string activity_;
};

}  // namespace ecoview
