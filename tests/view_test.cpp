// `ecoview view` as a user runs it, in a window on a virtual X display (Xvfb): a path played and
// shown with the shadow the geometry casts, replayed frame for frame by capture; keys moving the
// camera and recording a path; no display.
#include "floating_box.hpp"
#include "test_support.hpp"

#include <glm/glm.hpp>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

// An Xvfb server for the tests of this file; DISPLAY names it while it runs.
class VirtualDisplay : public ::testing::Environment {
 public:
  void SetUp() override {
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    pid_ = ::fork();
    if (pid_ == 0) {
      ::close(fds[0]);
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      const std::string fd = std::to_string(fds[1]);
      ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp", nullptr);
      ::_exit(127);
    }
    ::close(fds[1]);
    std::string number;
    char c = 0;
    while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    ASSERT_FALSE(number.empty()) << "Xvfb did not start (scripts/setup.sh installs it)";
    ::setenv("DISPLAY", (":" + number).c_str(), 1);
  }
  void TearDown() override {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    ::waitpid(pid_, nullptr, 0);
  }

 private:
  pid_t pid_ = -1;
};
const auto* const display = ::testing::AddGlobalTestEnvironment(new VirtualDisplay);

struct Rgb {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;
  float luminance(std::size_t i) const { return 0.2126f * pixels[3 * i] + 0.7152f * pixels[3 * i + 1] + 0.0722f * pixels[3 * i + 2]; }
};

Rgb load_rgb(const std::filesystem::path& png) {
  test::PngImage image = test::load_png(png, 3);
  return {image.width, image.height, std::move(image.samples)};
}

// The share of pixels in [x0, x1) x [y0, y1) (rows from the top) where two shots of one size differ.
double changed(const Rgb& a, const Rgb& b, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * a.width + x);
      n += a.pixels[i] != b.pixels[i] || a.pixels[i + 1] != b.pixels[i + 1] || a.pixels[i + 2] != b.pixels[i + 2];
    }
  }
  return static_cast<double>(n) / ((x1 - x0) * (y1 - y0));
}
double changed(const Rgb& a, const Rgb& b) { return changed(a, b, 0, 0, a.width, a.height); }

// A box over the plane, the camera above looking down at a slant, the light from the side.
FloatingBox box_scene() {
  FloatingBox s;
  s.box_min = {-1.5f, 3.0f, -1.5f};
  s.box_max = {1.5f, 5.0f, 1.5f};
  s.light.type = shadow::LightType::directional;
  s.light.direction = glm::normalize(glm::vec3(0.7f, -1.0f, 0.2f));
  s.camera.position = {0.0f, 22.0f, 16.0f};
  s.camera.target = {3.0f, 0.0f, 0.0f};
  return s;
}

// Two keys a second apart, the last at the scene's camera.
std::string path_to(const shadow::Camera& camera) {
  char text[512];
  std::snprintf(text, sizeof text,
                R"([{"t": 0, "position": [%g, %g, %g], "target": [%g, %g, %g]}, {"t": 1, "position": [%g, %g, %g], "target": [%g, %g, %g]}])",
                camera.position.x - 6.0, camera.position.y, camera.position.z, camera.target.x - 6.0, camera.target.y,
                camera.target.z, camera.position.x, camera.position.y, camera.position.z, camera.target.x, camera.target.y,
                camera.target.z);
  return text;
}

// The path at 5 frames per second for `frames` frames, the last one's window into `shot`.
std::vector<std::string> play_args(const TempDir& dir, const std::string& method, int frames, const std::string& shot) {
  return {"view", "--scene", (dir / "box.json").string(), "--play", (dir / "path.json").string(), "--fps", "5", "--exit-after", std::to_string(frames),
          "--size", "320x240", "--method", method, "--no-hud", "--screenshot", (dir / shot).string()};
}

TEST(View, PlaysAPathAndShowsTheShadowTheGeometryCasts) {
  const TempDir dir;
  const FloatingBox scene = box_scene();
  write_text(dir / "box.json", scene.scene_json());
  write_text(dir / "path.json", path_to(scene.camera));
  // Frame 5 is at t = 1 s, the last key: the scene's camera.
  CommandResult r = run_ecoview(play_args(dir, "uniform", 6, "shadowed.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("view: 6 frames"), std::string::npos) << r.out;
  r = run_ecoview(play_args(dir, "none", 6, "unshadowed.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Rgb shadowed = load_rgb(dir / "shadowed.png"), unshadowed = load_rgb(dir / "unshadowed.png");
  ASSERT_EQ(shadowed.width, 320);
  ASSERT_EQ(shadowed.height, 240);
  ASSERT_EQ(unshadowed.pixels.size(), shadowed.pixels.size());

  // In shadow where the frame is darker than the same frame without shadows.
  Image8 visibility{320, 240, 1, {}};
  for (std::size_t i = 0; i < shadowed.pixels.size() / 3; ++i) {
    visibility.samples.push_back(shadowed.luminance(i) < 0.9f * unshadowed.luminance(i) ? 0 : 255);
  }
  const TruthComparison c = compare_with_truth(scene, visibility, 2);
  EXPECT_GE(c.shadowed, 500u) << "the shadow is not in view";
  EXPECT_GE(c.lit_agreement(), 0.995);
  EXPECT_GE(c.shadowed_agreement(), 0.99);
}

TEST(View, PathReplaysInCaptureFrameForFrame) {
  const TempDir dir;
  const FloatingBox scene = box_scene();
  write_text(dir / "box.json", scene.scene_json());
  write_text(dir / "path.json", path_to(scene.camera));
  for (const char* method : {"uniform", "psm"}) {
    // Frame 3, at t = 0.6 s: between the keys, where the spline interpolates.
    const CommandResult v = run_ecoview(play_args(dir, method, 4, "view.png"));
    ASSERT_EQ(v.exit_code, 0) << v.err;
    const CommandResult c = run_ecoview({"capture", "--scene", (dir / "box.json").string(), "--path", (dir / "path.json").string(),
                                         "--fps", "5", "--frames", "0:4", "--size", "320x240", "--method", method, "--force",
                                         "--out", (dir / "capture").string()});
    ASSERT_EQ(c.exit_code, 0) << c.err;
    EXPECT_EQ(read_bytes(dir / "view.png"), read_bytes(dir / "capture" / "color_00003.png")) << method;
  }
}

// A point of the summary line ("camera at (x, y, z) looking at (x, y, z)") after `label`.
glm::vec3 summary_point(const std::string& out, const std::string& label) {
  glm::vec3 p(NAN);
  const auto at = out.find(label + " (");
  if (at != std::string::npos) std::sscanf(out.c_str() + at + label.size(), " (%f, %f, %f)", &p.x, &p.y, &p.z);
  return p;
}
glm::vec3 final_position(const std::string& out) { return summary_point(out, "camera at"); }
glm::vec3 final_target(const std::string& out) { return summary_point(out, "looking at"); }

// Runs the viewer on the box scene with `options`, and once it shows its first frame, the xdotool
// commands of `keys` (one per line, in its window); returns the viewer's output.
CommandResult view_with_keys(const TempDir& dir, const std::string& options, const std::string& keys) {
  write_text(dir / "box.json", box_scene().scene_json());
  const std::string out = (dir / "out.txt").string();
  return run_shell("timeout 120 \"$ecoview_binary\" view --scene " + shell_quote((dir / "box.json").string()) +
                   " " + options + " >" + shell_quote(out) + " & pid=$!\n"
                   "for i in $(seq 600); do grep -q 'first frame' " + shell_quote(out) + " && break; sleep 0.1; done\n"
                   "grep -q 'first frame' " + shell_quote(out) + " || { kill $pid; echo 'no first frame in 60 s' >&2; exit 4; }\n"
                   "window=$(timeout 30 xdotool search --sync --name '^ecoview') || { kill $pid; exit 3; }\n"
                   "xdotool windowfocus --sync $window && sleep 0.3\n" + keys +
                   "\nsleep 0.3 && xdotool key Escape\n"
                   "wait $pid; status=$?; cat " + shell_quote(out) + "; exit $status");
}

// Keys typed into the window through the X server (xdotool), once it shows its first frame: R
// starts recording, W held for a second flies forward, R stops, Esc closes.
TEST(View, KeysFlyTheCameraAndRecordAPath) {
  const TempDir dir;
  const FloatingBox scene = box_scene();
  const std::string path = (dir / "recorded.json").string();
  const CommandResult r = view_with_keys(dir, "--size 320x240 --no-hud --record " + shell_quote(path),
                                         "xdotool key r && sleep 0.3 && xdotool keydown w && sleep 1 && xdotool keyup w && "
                                         "sleep 0.3 && xdotool key r");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;

  // Forward along the view. How far depends on how long the key was really held on a loaded
  // machine; that the distance follows the time is FlightCamera.MotionDoesNotDependOnTheFrameRate's.
  const glm::vec3 moved = final_position(r.out) - scene.camera.position;
  ASSERT_GT(glm::length(moved), 0.01f * scene.camera.far) << r.out;
  EXPECT_GT(glm::dot(glm::normalize(moved), scene.camera.forward()), 0.999f) << r.out;

  // The recorded path starts at t = 0 and ends where the window's camera stopped; played in the
  // viewer, it takes the camera there again, and its frames are capture's.
  const std::string keys = read_bytes(path);
  EXPECT_EQ(keys.find("{\"t\":0.0,"), 4u) << keys.substr(0, 200);
  const CommandResult replay = run_ecoview({"view", "--scene", (dir / "box.json").string(), "--play", path, "--fps", "1",
                                            "--exit-after", "5", "--size", "64x48"});
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_LT(glm::length(final_position(replay.out) - final_position(r.out)), 1e-3f) << replay.out;
  const CommandResult shown = run_ecoview({"view", "--scene", (dir / "box.json").string(), "--play", path, "--fps", "10",
                                           "--exit-after", "6", "--size", "64x48", "--no-hud", "--screenshot", (dir / "shown.png").string()});
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  const CommandResult captured = run_ecoview({"capture", "--scene", (dir / "box.json").string(), "--path", path, "--fps", "10",
                                              "--frames", "5:6", "--size", "64x48", "--out", (dir / "capture").string()});
  ASSERT_EQ(captured.exit_code, 0) << captured.err;
  EXPECT_EQ(read_bytes(dir / "shown.png"), read_bytes(dir / "capture" / "color_00005.png"));
}

// O orbits around the surface in the middle of the frame: the plane at the scene camera's target
// (the box is off that line of sight). D circles; the camera keeps looking at that point from
// the same distance. P writes the frame shown as capture names it.
TEST(View, OrbitCirclesTheSurfaceInViewAndPWritesTheFrame) {
  const TempDir dir;
  const FloatingBox scene = box_scene();
  const CommandResult r = view_with_keys(dir, "--size 320x240 --no-hud --out " + shell_quote(dir.path().string()),
                                         "xdotool key o && sleep 0.3 && xdotool keydown d && sleep 0.5 && xdotool keyup d && "
                                         "sleep 0.3 && xdotool key p && sleep 0.5");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const glm::vec3 position = final_position(r.out), target = final_target(r.out);
  const float distance = glm::length(scene.camera.target - scene.camera.position);
  EXPECT_LT(glm::length(target - scene.camera.target), 0.01f * distance) << r.out;
  EXPECT_NEAR(glm::length(target - position), distance, 0.01f * distance) << r.out;
  EXPECT_GT(glm::length(position - scene.camera.position), 1.0f) << "the camera did not circle: " << r.out;

  std::vector<std::string> written;
  for (const std::string& f : files_in(dir.path())) {
    if (f.rfind("color_", 0) == 0) written.push_back(f);
  }
  ASSERT_EQ(written.size(), 1u) << r.out;
  const Rgb frame = load_rgb(dir / written.front());
  EXPECT_EQ(frame.width, 320);
  EXPECT_EQ(frame.height, 240);
}

// Esc ends the run before --exit-after's count: the screenshot is the frame Esc closed, the same
// as a frame counted out (the camera stays where the scene puts it).
TEST(View, EscWritesTheScreenshotOfTheFrameItCloses) {
  const TempDir dir;
  const CommandResult r = view_with_keys(dir, "--size 320x240 --no-hud --exit-after 100000 --screenshot " +
                                                  shell_quote((dir / "esc.png").string()), "");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const CommandResult counted = run_ecoview({"view", "--scene", (dir / "box.json").string(), "--size", "320x240", "--no-hud",
                                             "--exit-after", "2", "--screenshot", (dir / "counted.png").string()});
  ASSERT_EQ(counted.exit_code, 0) << counted.err;
  EXPECT_EQ(read_bytes(dir / "esc.png"), read_bytes(dir / "counted.png"));
}

// The box scene's window of `size` after two frames with `options`, shot into `dir`/`name`.
Rgb window_shot(const TempDir& dir, const std::string& name, const std::string& size, const std::vector<std::string>& options) {
  write_text(dir / "box.json", box_scene().scene_json());
  std::vector<std::string> args = {"view", "--scene", (dir / "box.json").string(), "--size", size, "--exit-after", "2",
                                   "--screenshot", (dir / name).string()};
  args.insert(args.end(), options.begin(), options.end());
  const CommandResult r = run_ecoview(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return load_rgb(dir / name);
}

// The HUD draws its full panel, the shadow-map inset and the aliasing overlay where they belong:
// each changes its part of the window and leaves the rest as the frame alone shows it.
TEST(View, HudDrawsThePanelTheInsetAndTheOverlay) {
  const TempDir dir;
  auto shot = [&](const std::string& name, const std::vector<std::string>& options) { return window_shot(dir, name, "640x480", options); };
  const Rgb bare = shot("bare.png", {"--no-hud"}), panel = shot("panel.png", {"--full-hud"});
  const Rgb inset = shot("inset.png", {"--full-hud", "--shadow-map-inset"});
  const Rgb overlay = shot("overlay.png", {"--full-hud", "--aliasing-overlay"});
  for (const Rgb* shot : {&bare, &panel, &inset, &overlay}) ASSERT_EQ(shot->pixels.size(), 640u * 480u * 3u);
  EXPECT_GT(changed(bare, panel, 10, 10, 300, 100), 0.9) << "no panel at the top left";
  EXPECT_EQ(changed(bare, panel, 0, 440, 640, 480), 0.0) << "the panel reaches the bottom";
  EXPECT_GT(changed(panel, inset, 520, 40, 630, 260), 0.9) << "no inset at the top right";
  EXPECT_EQ(changed(panel, inset, 0, 440, 640, 480), 0.0);
  // The overlay tints every surface below the panel; the sky above the horizon keeps its colour.
  EXPECT_GT(changed(panel, overlay, 0, 440, 640, 480), 0.9) << "no aliasing overlay";
}

// The HUD's tests' window: the size the issue measured it at.
Rgb hud_shot(const TempDir& dir, const std::string& name, const std::vector<std::string>& options) {
  return window_shot(dir, name, "960x540", options);
}

// The HUD starts folded to its summary lines, a small part of the window; unfolded (--full-hud)
// it covers many times that.
TEST(ViewerHud, TheFoldedPanelCoversUnderATwentiethOfTheWindow) {
  const TempDir dir;
  const Rgb bare = hud_shot(dir, "bare.png", {"--no-hud"}), folded = hud_shot(dir, "folded.png", {});
  const Rgb full = hud_shot(dir, "full.png", {"--full-hud"});
  for (const Rgb* shot : {&folded, &full}) ASSERT_EQ(shot->pixels.size(), bare.pixels.size());
  ASSERT_EQ(bare.pixels.size(), 960u * 540u * 3u);
  EXPECT_GT(changed(bare, folded, 8, 8, 200, 30), 0.9) << "no summary at the top left";
  EXPECT_LT(changed(bare, folded), 0.05);
  EXPECT_GT(changed(bare, full), 4 * changed(bare, folded));
}

// Keys typed into a window of the box scene at 960x540 (the folded HUD at first); the window as
// it was when Esc closed it, from `dir`/`name`.
Rgb shot_after_keys(const TempDir& dir, const std::string& name, const std::string& keys) {
  const CommandResult r = view_with_keys(dir, "--size 960x540 --exit-after 100000 --screenshot " + shell_quote((dir / name).string()), keys);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  return load_rgb(dir / name);
}

// Tab unfolds the full panel; H hides it and the rest of the HUD, leaving the frame alone.
TEST(ViewerHud, TabUnfoldsTheFullPanelAndHHidesEverything) {
  const TempDir dir;
  const Rgb bare = hud_shot(dir, "bare.png", {"--no-hud"}), folded = hud_shot(dir, "folded.png", {});
  const Rgb unfolded = shot_after_keys(dir, "tab.png", "xdotool key Tab && sleep 0.5");
  const Rgb hidden = shot_after_keys(dir, "tab_h.png", "xdotool key Tab && sleep 0.3 && xdotool key h && sleep 0.5");
  for (const Rgb* shot : {&folded, &unfolded, &hidden}) ASSERT_EQ(shot->pixels.size(), bare.pixels.size());
  EXPECT_GT(changed(bare, unfolded), 4 * changed(bare, folded));
  EXPECT_EQ(changed(bare, hidden), 0.0);
}

TEST(View, WithoutADisplayPointsToCapture) {
  const CommandResult r = run_shell("unset DISPLAY WAYLAND_DISPLAY; ecoview view --scene courtyard --exit-after 1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("ecoview capture"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(View, BadOptionsAreNamed) {
  const TempDir dir;
  CommandResult r = run_ecoview({"view", "--scene", "courtyard", "--screenshot", (dir / "a.png").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--screenshot"), std::string::npos) << r.err;
  r = run_ecoview({"view", "--scene", "courtyard", "--play", (dir / "missing.json").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("missing.json"), std::string::npos) << r.err;
  write_text(dir / "scene.json", R"({"camera": {"position": [0, 1, 2], "target": [0, 1, 2]}})");
  r = run_shell("unset DISPLAY WAYLAND_DISPLAY; ecoview view --scene " + shell_quote((dir / "scene.json").string()));
  EXPECT_EQ(r.exit_code, 2) << "a bad scene is bad input, display or not";
  EXPECT_NE(r.err.find("scene.json"), std::string::npos) << r.err;
  write_text(dir / "bad.json", R"([{"t": 0, "position": [0, 1, 2], "target": [0, 1, 2]}])");
  r = run_ecoview({"view", "--scene", "courtyard", "--play", (dir / "bad.json").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  r = run_ecoview({"view", "--scene", "courtyard", "--fps", "0"});
  EXPECT_EQ(r.exit_code, 2) << "--fps 0 is not the clock";
  EXPECT_NE(r.err.find("--fps"), std::string::npos) << r.err;
  r = run_ecoview({"view", "--scene", "courtyard", "--exit-after", "1", "--screenshot", dir.path().string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is a folder"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ecoview::test
