// `ecoview capture` as a user runs it: outputs, determinism, resume, and bad input.
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace ecoview::test {
namespace {

struct Gray {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;
};

Gray load_gray(const std::filesystem::path& png) {
  test::PngImage image = test::load_png(png, 1);
  return {image.width, image.height, std::move(image.samples)};
}

TEST(Capture, DefaultSceneFrameIsLitAndShadowed) {
  const TempDir dir;
  const CommandResult r = run_ecoview({"capture", "--aov", "color,shadow,depth", "--size", "320x180", "--out", dir.path()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(files_in(dir.path()), (std::vector<std::string>{"color_00000.png", "depth_00000.png", "shadow_00000.png"}));
  const Gray shadow = load_gray(dir / "shadow_00000.png");
  ASSERT_EQ(shadow.width, 320);
  ASSERT_EQ(shadow.height, 180);
  const auto dark = std::count_if(shadow.pixels.begin(), shadow.pixels.end(), [](unsigned char v) { return v < 128; });
  // The default scene is the ecosystem: foliage in sun and shade, and the sky (lit).
  EXPECT_GT(dark, 320 * 180 / 20) << "no shadow in the default frame";
  EXPECT_GT(static_cast<long>(shadow.pixels.size()) - dark, 320 * 180 / 4) << "too little light in the default frame";
}

// Without --method a frame gets the perspective shadow map, the method this project is about.
TEST(Capture, TheDefaultMethodIsThePerspectiveShadowMap) {
  const TempDir dir;
  const CommandResult r = run_ecoview({"capture", "--scene", "courtyard", "--size", "64x36", "--aov", "none", "--stats",
                                       (dir / "stats.json").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(read_bytes(dir / "stats.json")).at(0).at("method"), "psm");
}

TEST(Capture, SameFrameGivesSameBytes) {
  for (const char* backend : {"egl", "osmesa"}) {
    const TempDir a, b;
    const std::vector<std::string> args = {"capture", "--backend", backend, "--scene", "courtyard", "--path", "courtyard", "--frames", "3:5",
                                           "--aov", "color,shadow,depth", "--size", "256x160"};
    auto with_out = [&](const TempDir& d) { auto v = args; v.insert(v.end(), {"--out", d.path().string()}); return v; };
    const CommandResult ra = run_ecoview(with_out(a));
    if (ra.exit_code == 1 && ra.err.find("built without OSMesa") != std::string::npos) continue;
    ASSERT_EQ(ra.exit_code, 0) << ra.err;
    ASSERT_EQ(run_ecoview(with_out(b)).exit_code, 0);
    const std::vector<std::string> files = files_in(a.path());
    ASSERT_EQ(files.size(), 6u);
    ASSERT_EQ(files, files_in(b.path()));
    for (const std::string& f : files) EXPECT_EQ(read_bytes(a / f), read_bytes(b / f)) << backend << " " << f;
  }
}

// A scene with no mesh drawn as points renders to the same bytes with points on and off (the
// benchmarks turn them off there: for_scene).
TEST(Capture, ASceneWithoutPointMeshesRendersTheSameWithPointsOnOrOff) {
  const TempDir dir;
  for (const char* geometry : {"points", "polygons"}) {
    ASSERT_EQ(run_ecoview({"capture", "--scene", "field", "--geometry", geometry, "--method", "psm", "--size", "160x90",
                           "--frames", "0:2", "--aov", "color,shadow", "--out", (dir / geometry).string()}).exit_code, 0);
  }
  for (const char* file : {"color_00001.png", "shadow_00001.png"}) {
    EXPECT_EQ(read_bytes(dir / "points" / file), read_bytes(dir / "polygons" / file)) << file;
  }
}

TEST(Capture, FramesAlongAPathDiffer) {
  const TempDir dir;
  ASSERT_EQ(run_ecoview({"capture", "--scene", "courtyard", "--path", "courtyard", "--frames", "0:31:", "--out", dir.path()}).exit_code, 2);
  ASSERT_EQ(run_ecoview({"capture", "--scene", "courtyard", "--path", "courtyard", "--fps", "1", "--size", "160x90", "--out", dir.path()}).exit_code, 0);
  // The path lasts 3 s: at 1 frame per second, frames 0 to 3.
  ASSERT_EQ(files_in(dir.path()).size(), 4u);
  EXPECT_NE(read_bytes(dir / "color_00000.png"), read_bytes(dir / "color_00003.png"));
}

TEST(Capture, ResumesWhereItStopped) {
  const TempDir dir;
  const std::vector<std::string> args = {"capture", "--scene", "courtyard", "--path", "courtyard", "--frames", "0:3", "--size", "160x90",
                                         "--out", dir.path().string()};
  ASSERT_EQ(run_ecoview(args).exit_code, 0);
  const std::string frame1 = read_bytes(dir / "color_00001.png");
  const auto frame0_time = std::filesystem::last_write_time(dir / "color_00000.png");
  std::filesystem::remove(dir / "color_00001.png");

  const CommandResult resumed = run_ecoview(args);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("wrote 1 frame(s)"), std::string::npos) << resumed.out;
  EXPECT_NE(resumed.out.find("2 already there"), std::string::npos) << resumed.out;
  EXPECT_EQ(read_bytes(dir / "color_00001.png"), frame1);
  EXPECT_EQ(std::filesystem::last_write_time(dir / "color_00000.png"), frame0_time);

  const CommandResult complete = run_ecoview(args);
  EXPECT_NE(complete.out.find("all 3 frames already"), std::string::npos) << complete.out;
  auto forced = args;
  forced.push_back("--force");
  EXPECT_NE(run_ecoview(forced).out.find("wrote 3 frame(s)"), std::string::npos);
  EXPECT_EQ(files_in(dir.path()).size(), 3u);  // no temporary files left behind
}

// Each shipped scene renders on each headless backend (the default scene, the ecosystem, above).
class ShippedScene : public testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(ShippedScene, CapturesWithShadowsInView) {
  const auto& [scene, backend] = GetParam();
  const TempDir dir;
  const CommandResult r = run_ecoview({"capture", "--scene", scene, "--backend", backend, "--size", "192x108",
                                       "--aov", "shadow", "--out", dir.path().string()});
  if (r.exit_code == 1 && r.err.find("built without OSMesa") != std::string::npos) GTEST_SKIP() << "this build has no OSMesa backend";
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("scene: data/scenes/" + scene + ".json"), std::string::npos) << r.out;
  const Gray shadow = load_gray(dir / "shadow_00000.png");
  EXPECT_GT(std::count_if(shadow.pixels.begin(), shadow.pixels.end(), [](unsigned char v) { return v < 128; }), 100)
      << "no shadow in " << scene;
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScene,
                         testing::Combine(testing::Values("courtyard", "square", "street", "chess", "single", "landscape"),
                                          testing::Values("egl", "osmesa")),
                         [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });

TEST(Capture, CrowdAndTrafficMoveTheSameWayInEveryProcess) {
  for (const char* scene : {"square", "street"}) {
    const TempDir a, b;
    for (const TempDir* dir : {&a, &b}) {
      // Frames 30 and 60: t = 1 s and 2 s.
      ASSERT_EQ(run_ecoview({"capture", "--scene", scene, "--frames", "30:31", "--size", "192x108", "--out", dir->path().string()}).exit_code, 0);
      ASSERT_EQ(run_ecoview({"capture", "--scene", scene, "--frames", "60:61", "--size", "192x108", "--out", dir->path().string()}).exit_code, 0);
    }
    EXPECT_EQ(read_bytes(a / "color_00030.png"), read_bytes(b / "color_00030.png")) << scene;
    EXPECT_EQ(read_bytes(a / "color_00060.png"), read_bytes(b / "color_00060.png")) << scene;
    EXPECT_NE(read_bytes(a / "color_00030.png"), read_bytes(a / "color_00060.png")) << scene << ": nothing moved in 1 s";
  }
}

TEST(Density, QuickRunWritesResultsChartsAndReport) {
  const TempDir dir;
  const CommandResult r = run_ecoview({"density", "--quick", "--scene", "square", "--size", "320x180", "--out", dir.path().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* file : {"results.json", "results.csv", "chart_quality.png", "chart_scale.png", "chart_thirds.png",
                           "report.html", "images/polygons.png", "images/points.png", "images/difference.png",
                           "images/reference.png", "images/points_in_scene.png", "images/polygons_in_scene.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  // The report says the run was quick, and shows the machine as a table.
  const std::string report = read_bytes(dir / "report.html");
  EXPECT_NE(report.find("(quick run)"), std::string::npos);
  EXPECT_NE(report.find("<th>cores</th>"), std::string::npos);
  const nlohmann::json results = nlohmann::json::parse(read_bytes(dir / "results.json"));
  EXPECT_EQ(results["machine"]["cores"].get<int>() > 0, true);
  ASSERT_GE(results["runs"].size(), 6u);
  for (const auto& run : results["runs"]) {
    ASSERT_TRUE(run.contains("params") && run.contains("figures"));
    for (const auto& figure : run["figures"].items()) {
      EXPECT_TRUE(figure.value().is_number() && std::isfinite(figure.value().get<double>())) << figure.key();
    }
  }
  // A still camera renders the same frame twice.
  const auto temporal = std::find_if(results["runs"].begin(), results["runs"].end(),
                                     [](const nlohmann::json& run) { return run["params"]["sweep"] == "temporal"; });
  ASSERT_NE(temporal, results["runs"].end());
  EXPECT_EQ((*temporal)["figures"]["still_changed"].get<double>(), 0.0);
  // The points' and the polygons' fidelity to the 4 × 4-sample reference, in their ranges.
  for (const auto& run : results["runs"]) {
    if (run["params"]["sweep"] != "quality") continue;
    for (const char* ssim : {"ssim", "ssim_polygons"}) {
      EXPECT_GT(run["figures"][ssim].get<double>(), 0.0) << ssim;
      EXPECT_LE(run["figures"][ssim].get<double>(), 1.0) << ssim;
    }
    EXPECT_GT(run["figures"]["psnr_polygons"].get<double>(), 10.0);
  }
  // The scale sweep times every stand with points, and with polygons only those up to the plan's
  // limit (the quick plan's: the smaller stand).
  std::multiset<std::pair<std::string, int>> scale_runs;
  for (const auto& run : results["runs"]) {
    if (run["params"]["sweep"] == "scale") scale_runs.emplace(run["params"]["geometry"], run["params"]["instances"]);
  }
  EXPECT_EQ(scale_runs, (std::multiset<std::pair<std::string, int>>{{"points", 300}, {"points", 3000}, {"polygons", 300}}));
  // The landscape sweep: the same landscape over areas holding 10^6 and 10^8 plants (10 times the
  // side), each frame drawing plants made for its view.
  std::vector<std::pair<double, double>> landscapes;  // plants, side
  for (const auto& run : results["runs"]) {
    if (run["params"]["sweep"] != "landscape") continue;
    landscapes.emplace_back(run["params"]["plants"].get<double>(), run["params"]["side_m"].get<double>());
    EXPECT_GT(run["figures"]["pool_plants"].get<double>(), 1000.0);
    EXPECT_GT(run["figures"]["points"].get<double>(), 1000.0);
  }
  ASSERT_EQ(landscapes.size(), 2u);
  EXPECT_NEAR(landscapes[0].first, 1e6, 0.05e6);
  EXPECT_NEAR(landscapes[1].first, 1e8, 0.05e8);
  EXPECT_NEAR(landscapes[1].second / landscapes[0].second, 10.0, 0.01);
}

// The paper suite renders each of its figures, measured against the exact reference; in its bias
// sweep a large constant bias lifts the shadows off their casters (more leak than the default),
// and sooner in 16 bits, whose steps are larger than 32-bit float's anywhere in 0..1.
TEST(Bench, PaperSuiteQuickRunRendersEveryFigure) {
  const TempDir dir;
  const CommandResult r = run_ecoview({"bench", "--suite", "paper", "--quick", "--size", "320x180", "--out", dir.path().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* file : {"results.json", "results.csv", "report.html", "chart_bias.png", "chart_depth.png",
                           "images/paper_fig1_psm_map.png", "images/paper_fig8_halves.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  const nlohmann::json results = nlohmann::json::parse(read_bytes(dir / "results.json"));
  std::set<std::string> figures, depth_formats;
  std::map<std::string, double> leak;  // the constant sweep's, by format and constant: "32f 4"
  for (const auto& run : results["runs"]) {
    figures.insert(run["params"]["figure"].get<std::string>());
    for (const auto& figure : run["figures"].items()) {
      EXPECT_TRUE(figure.value().is_number() && std::isfinite(figure.value().get<double>())) << figure.key();
    }
    if (run["params"]["figure"] == "bias" && run["params"]["bias_slope"] == 2.0) {
      std::ostringstream key;
      key << run["params"]["shadow_depth"].get<std::string>() << " " << run["params"]["bias_constant"].get<double>();
      leak[key.str()] = run["figures"]["leak"].get<double>();
    }
    if (run["params"]["figure"] == "depth") depth_formats.insert(run["params"]["shadow_depth"].get<std::string>());
  }
  EXPECT_EQ(figures, (std::set<std::string>{"fig1", "fig8", "fig9", "fig10", "ipsm", "overhead", "bias", "depth"}));
  EXPECT_EQ(depth_formats, (std::set<std::string>{"16", "24", "32f"}));
  for (const char* key : {"32f 4", "32f 1e+07", "16 1000", "32f 1000"}) ASSERT_TRUE(leak.count(key)) << key;
  EXPECT_GT(leak["32f 1e+07"], leak["32f 4"]);
  EXPECT_GT(leak["16 1000"], leak["32f 1000"]);
  EXPECT_EQ(run_ecoview({"bench", "--suite", "papers", "--quick", "--out", (dir / "other").string()}).exit_code, 2);
}

// The quality runs' reference is drawn at 4 × 4 samples a pixel: a frame size whose reference the
// driver cannot draw is refused with that reason, before any run.
TEST(Density, ASizeWhoseReferenceIsTooLargeIsRefused) {
  const TempDir dir;
  const CommandResult r = run_ecoview({"density", "--quick", "--scene", "square", "--size", "4200x200", "--out", dir.path().string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--size"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("4 × 4 samples"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "results.json"));
}

// The runs that no other run of their scene's timed sweeps beats in both frame_ms and err, by
// comparing every pair: "scene method shadow_size".
std::set<std::string> pareto_front_of(const nlohmann::json& runs) {
  std::set<std::string> front;
  const auto timed = [](const nlohmann::json& run) { return run["params"]["sweep"] == "tradeoff" || run["params"]["sweep"] == "scenes"; };
  for (const auto& run : runs) {
    if (!timed(run)) continue;
    const double ms = run["figures"]["frame_ms"], err = run["figures"]["err"];
    const bool beaten = std::any_of(runs.begin(), runs.end(), [&](const nlohmann::json& other) {
      const double other_ms = other["figures"].value("frame_ms", 0.0), other_err = other["figures"].value("err", 0.0);
      return timed(other) && other["params"]["scene"] == run["params"]["scene"] && other_ms <= ms && other_err <= err &&
             (other_ms < ms || other_err < err);
    });
    if (!beaten) {
      front.insert(run["params"]["scene"].get<std::string>() + " " + run["params"]["method"].get<std::string>() + " " +
                   std::to_string(run["params"]["shadow_size"].get<int>()));
    }
  }
  return front;
}

// Also: the report opens with the quick run's mark and the summary of each scene's Pareto front,
// results.json says the run is quick, names the machine and, against a baseline with no runs,
// counts every run as new.
TEST(Bench, QuickRunWritesResultsChartsCropsAndReportAndVolumesMatchTheReference) {
  const TempDir dir;
  write_text(dir / "empty_baseline.json", R"({"machine": {"git": "before"}, "quick": true, "runs": []})");
  const CommandResult r = run_ecoview({"bench", "--quick", "--size", "320x180", "--baseline", (dir / "empty_baseline.json").string(),
                                       "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* file : {"results.json", "results.csv", "chart_tradeoff.png", "chart_equal_err.png", "chart_scenes.png", "chart_stability.png",
                           "chart_flythrough.png", "report.html", "images/crop_field_psm.png", "images/crop_field_reference.png",
                           "images/crop_chess_psm+silhouette.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / file)) << file;
  }
  const nlohmann::json results = nlohmann::json::parse(read_bytes(dir / "out" / "results.json"));
  std::set<std::string> sweeps;
  int volumes = 0;
  for (const auto& run : results["runs"]) {
    sweeps.insert(run["params"]["sweep"].get<std::string>());
    for (const auto& figure : run["figures"].items()) {
      EXPECT_TRUE(figure.value().is_number() && std::isfinite(figure.value().get<double>())) << figure.key();
    }
    // Shadow volumes are exact for polygons: they agree with the reference on the field's posts and
    // the courtyard's blocks (the trade-off sweep). On the chess board's turned pieces they do not
    // quite: 0.13 % here, 0.18 % in the full run, shadowed where the reference is lit.
    if (run["params"]["method"] == "volumes" && run["params"]["sweep"] == "tradeoff") {
      EXPECT_LT(run["figures"]["err"].get<double>(), 1e-3) << run["params"]["scene"];
      ++volumes;
    }
  }
  EXPECT_GT(volumes, 0);
  // The ray-traced reference is timed and on the chart, with no error against itself to speak of.
  const auto reference = std::find_if(results["runs"].begin(), results["runs"].end(), [](const nlohmann::json& run) {
    return run["params"]["sweep"] == "tradeoff" && run["params"]["method"] == "reference";
  });
  ASSERT_NE(reference, results["runs"].end());
  EXPECT_GT((*reference)["figures"]["frame_ms"].get<double>(), 0.0);
  EXPECT_LT((*reference)["figures"]["err"].get<double>(), 1e-4);
  EXPECT_EQ(sweeps, (std::set<std::string>{"tradeoff", "equal_err", "scenes", "stability", "crossing", "flythrough", "flicker"}));

  EXPECT_EQ(results["quick"], true);
  for (const char* field : {"cpu", "renderer", "gl_version", "backend", "compiler", "git"}) {
    EXPECT_FALSE(results["machine"][field].get<std::string>().empty()) << field;
  }
  EXPECT_GT(results["machine"]["cores"].get<int>(), 0);
  std::set<std::string> front;
  for (const auto& [scene, points] : results["pareto_front"].items()) {
    for (const auto& p : points) front.insert(scene + " " + p["method"].get<std::string>() + " " + std::to_string(p["shadow_size"].get<int>()));
  }
  EXPECT_EQ(front, pareto_front_of(results["runs"]));
  EXPECT_EQ(results["baseline"]["runs_only_here"], results["runs"].size());
  EXPECT_EQ(results["baseline"]["git"], "before");
  EXPECT_TRUE(results["baseline"]["changes"].empty());

  const std::string report = read_bytes(dir / "out" / "report.html");
  const std::size_t quick = report.find("(quick run)"), summary = report.find("Summary: the best at each cost"),
                    baseline = report.find("Against the baseline"), charts = report.find("<img");
  ASSERT_NE(summary, std::string::npos);
  EXPECT_LT(quick, summary);
  EXPECT_LT(summary, baseline);
  EXPECT_LT(baseline, charts);
}

// A baseline that is not a bench's results.json is refused before any run, naming the file and
// the field, and nothing is written.
TEST(Bench, ABaselineThatIsNotBenchResultsIsRefusedNamingTheFileAndTheField) {
  const TempDir dir;
  write_text(dir / "scene.json", R"({"machine": {}, "runs": [{"params": {}, "figures": {"err": "low"}}]})");
  const CommandResult r = run_ecoview({"bench", "--quick", "--baseline", (dir / "scene.json").string(), "--out", (dir / "out").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find((dir / "scene.json").string() + ": runs[0].figures.err: expected a number"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  // The paper suite has no runs to compare.
  const CommandResult paper = run_ecoview({"bench", "--suite", "paper", "--quick", "--baseline", (dir / "scene.json").string(),
                                           "--out", (dir / "out").string()});
  EXPECT_EQ(paper.exit_code, 2) << paper.err;
  EXPECT_NE(paper.err.find("--baseline"), std::string::npos) << paper.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  // A full run's figures are not a quick run's: other scenes, sizes and frame counts.
  write_text(dir / "full.json", R"({"machine": {}, "quick": false, "runs": []})");
  const CommandResult full = run_ecoview({"bench", "--quick", "--baseline", (dir / "full.json").string(), "--out", (dir / "out").string()});
  EXPECT_EQ(full.exit_code, 2) << full.err;
  EXPECT_NE(full.err.find((dir / "full.json").string() + ": quick:"), std::string::npos) << full.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(Capture, RendersARealGltfFile) {
  const auto cube = shared_testdata_dir() / "gltf" / "Cube" / "Cube.gltf";
  if (!std::filesystem::exists(cube)) GTEST_SKIP() << cube << " is absent";
  const TempDir dir;
  write_text(dir / "scene.json", R"({"camera": {"position": [4, 4, 6], "target": [0, 0.5, 0]},
    "lights": [{"type": "directional", "direction": [0.5, -1, 0.3]}],
    "objects": [{"type": "plane", "center": [0, -2, 0], "size": [10, 10]},
                {"type": "mesh", "file": ")" + cube.string() + R"("}]})");
  const CommandResult r = run_ecoview({"capture", "--scene", (dir / "scene.json").string(), "--aov", "shadow",
                                       "--size", "160x90", "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Gray shadow = load_gray(dir / "out" / "shadow_00000.png");
  EXPECT_GT(std::count_if(shadow.pixels.begin(), shadow.pixels.end(), [](unsigned char v) { return v < 128; }), 50);
}

TEST(Capture, HelpExitsZero) {
  const CommandResult r = run_ecoview({"capture", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("--shadow-size"), std::string::npos);
}

// The commands `ecoview --help` lists, and ecoview itself (""), each as the help names it.
std::vector<std::string> commands_and_ecoview() {
  const CommandResult r = run_ecoview({"--help"});
  std::vector<std::string> commands = {""};
  std::istringstream lines(r.out);
  bool listed = false;
  for (std::string line; std::getline(lines, line);) {
    if (listed && line.rfind("  ", 0) == 0) commands.push_back(line.substr(2, line.find(' ', 2) - 2));
    listed = listed ? !line.empty() : line == "Subcommands:";
  }
  return commands;
}

// Each command's help is read at a glance: no line longer than 100 characters, and each option on
// its own line (a description wrapped onto the next line would start with spaces, not a dash).
TEST(Help, EveryOptionIsOneLineOfAtMost100Characters) {
  const std::vector<std::string> commands = commands_and_ecoview();
  for (const char* expected : {"capture", "view", "density", "bench", "help"}) {
    EXPECT_NE(std::find(commands.begin(), commands.end(), expected), commands.end()) << expected;
  }
  for (const std::string& command : commands) {
    const CommandResult r = run_ecoview(command.empty() ? std::vector<std::string>{"--help"} : std::vector<std::string>{command, "--help"});
    ASSERT_EQ(r.exit_code, 0) << command << ": " << r.err;
    std::istringstream lines(r.out);
    int options = 0;
    bool in_options = false;
    for (std::string line; std::getline(lines, line);) {
      EXPECT_LE(line.size(), 100u) << command << ": " << line;
      if (in_options && !line.empty()) {
        EXPECT_EQ(line.rfind("  -", 0), 0u) << command << ": not an option's line: " << line;
        ++options;
      }
      in_options = in_options ? !line.empty() : line == "Options:";
    }
    EXPECT_GE(options, 1) << command;
  }
}

// `ecoview help` and `ecoview help COMMAND` print what --help prints; an unknown command is bad input.
TEST(Help, TheHelpCommandPrintsWhatHelpPrints) {
  for (const std::string& command : commands_and_ecoview()) {
    const CommandResult asked = run_ecoview(command.empty() ? std::vector<std::string>{"help"} : std::vector<std::string>{"help", command});
    const CommandResult option = run_ecoview(command.empty() ? std::vector<std::string>{"--help"} : std::vector<std::string>{command, "--help"});
    EXPECT_EQ(asked.exit_code, 0) << command << ": " << asked.err;
    EXPECT_EQ(asked.out, option.out) << command;
  }
  const CommandResult unknown = run_ecoview({"help", "paint"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("'paint'"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("capture"), std::string::npos) << unknown.err;
}

// A mistyped option sends the reader to the help of the command it was given to.
TEST(Help, AnUnknownOptionPointsToItsCommandsHelp) {
  for (const std::string& command : commands_and_ecoview()) {
    const CommandResult r = run_ecoview(command.empty() ? std::vector<std::string>{"--colour", "red"}
                                                        : std::vector<std::string>{command, "--colour", "red"});
    EXPECT_EQ(r.exit_code, 2) << command;
    const std::string help = command.empty() ? "see ecoview --help" : "see ecoview " + command + " --help";
    EXPECT_NE(r.err.find(help), std::string::npos) << command << ": " << r.err;
  }
}

// Output paths: a file where the --out folder would go, a folder where a frame's file goes, and
// --stats in the --out folder a first run makes; an empty file in a frame's place is no frame.
TEST(Capture, OutputPathsAreCheckedBeforeAnyWork) {
  const TempDir dir;
  write_text(dir / "file", "x");
  CommandResult r = run_ecoview({"capture", "--scene", "courtyard", "--out", (dir / "file" / "out").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("is a file, not a folder"), std::string::npos) << r.err;

  const std::filesystem::path out = dir / "out";
  std::filesystem::create_directories(out / "shadow_00001.png");
  r = run_ecoview({"capture", "--scene", "courtyard", "--size", "64x36", "--frames", "0:2", "--aov", "color,shadow",
                   "--out", out.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("shadow_00001.png exists and is not a file"), std::string::npos) << r.err;
  EXPECT_EQ(files_in(out), std::vector<std::string>{"shadow_00001.png"}) << "nothing rendered";

  const std::filesystem::path fresh = dir / "fresh";
  r = run_ecoview({"capture", "--scene", "courtyard", "--size", "64x36", "--stats", (fresh / "stats.json").string(),
                   "--out", fresh.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(std::filesystem::file_size(fresh / "stats.json"), 0u);
  write_text(fresh / "color_00000.png", "");
  r = run_ecoview({"capture", "--scene", "courtyard", "--size", "64x36", "--out", fresh.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(std::filesystem::file_size(fresh / "color_00000.png"), 0u) << "an empty file is rendered again";
}

// A method that takes only some kinds of light hands the others to the uniform map, and says so
// in one note: the courtyard's light 0 is directional, 1 a spot and 2 a point light; dpsm takes
// point and spot lights, lispsm directional ones, psm all.
TEST(Capture, AMethodSaysInANoteWhenItHandsTheLightToTheUniformMap) {
  struct Case {
    const char* method;
    const char* light;
    bool handed_over;
  };
  for (const Case& c : {Case{"dpsm", "0", true}, Case{"dpsm", "2", false}, Case{"lispsm", "1", true}, Case{"lispsm", "0", false},
                        Case{"psm", "1", false}}) {
    const TempDir dir;
    const CommandResult r = run_ecoview({"capture", "--scene", "courtyard", "--method", c.method, "--light", c.light, "--size", "64x36",
                                         "--out", dir.path().string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string note = std::string("ecoview: note: --method ") + c.method + " takes only ";
    EXPECT_EQ(r.err.find(note) != std::string::npos, c.handed_over) << c.method << " " << c.light << ": " << r.err;
    if (!c.handed_over) continue;
    const std::string line = r.err.substr(r.err.find(note), r.err.find('\n', r.err.find(note)) - r.err.find(note));
    EXPECT_NE(line.find("light " + std::string(c.light)), std::string::npos) << line;
    EXPECT_NE(line.find("uniform map"), std::string::npos) << line;
  }
}

// A frame takes things from the one before (the PSM's near plane, caster culling's receivers):
// a capture split anywhere gives the same bytes as one run, points and point casters included.
TEST(Capture, AFrameHasTheSameBytesWhereverACaptureIsSplit) {
  for (const char* method : {"psm", "uniform", "auto"}) {
    const TempDir whole, alone;
    const std::vector<std::string> args = {"capture", "--path", "ecosystem", "--method", method, "--size", "240x135",
                                           "--shadow-size", "512", "--aov", "color,shadow"};
    auto with = [&](const char* frames, const TempDir& d) {
      auto v = args;
      v.insert(v.end(), {"--frames", frames, "--out", d.path().string()});
      return v;
    };
    ASSERT_EQ(run_ecoview(with("0:3", whole)).exit_code, 0);
    ASSERT_EQ(run_ecoview(with("2:3", alone)).exit_code, 0);
    EXPECT_EQ(read_bytes(whole / "shadow_00002.png"), read_bytes(alone / "shadow_00002.png")) << method;
    EXPECT_EQ(read_bytes(whole / "color_00002.png"), read_bytes(alone / "color_00002.png")) << method;
  }
}

// A landscape's plants and ground are made where each frame's eye is: a frame flown to from 400 m
// away has the same bytes as the same frame started cold, whatever the pool held before it.
TEST(Capture, ALandscapeFrameHasTheSameBytesWhateverItsPoolHeldBefore) {
  const TempDir whole, alone, paths;
  const std::filesystem::path path = paths / "low_flight.json";
  // Westward, looking back east, from where more plants grow (23,755) to where fewer do (22,973):
  // the pool's room holds less each frame (GpuSampling.APoolRefilledWithFewerPlants… checks that
  // what it held before is not chosen).
  write_text(path, R"([{"t": 0, "position": [100, 45, 120], "target": [200, 20, 100]},
                       {"t": 3, "position": [-300, 45, 120], "target": [-200, 20, 100]}])");
  auto with = [&](const char* frames, const TempDir& d) {
    return std::vector<std::string>{"capture", "--scene", (source_dir() / "data/examples/landscape.json").string(), "--path",
                                    path.string(), "--fps", "1", "--size", "240x135", "--shadow-size", "512", "--stats",
                                    (d / "stats.json").string(), "--frames", frames, "--out", d.path().string()};
  };
  ASSERT_EQ(run_ecoview(with("0:4", whole)).exit_code, 0);
  ASSERT_EQ(run_ecoview(with("3:4", alone)).exit_code, 0);
  EXPECT_EQ(read_bytes(whole / "color_00003.png"), read_bytes(alone / "color_00003.png"));
  const nlohmann::json flown = nlohmann::json::parse(read_bytes(whole / "stats.json")).back()["landscape"];
  const nlohmann::json cold = nlohmann::json::parse(read_bytes(alone / "stats.json")).back()["landscape"];
  EXPECT_EQ(flown["plants"], cold["plants"]);
  EXPECT_GT(flown["plants"].get<int>(), 1000);
  EXPECT_GT(flown["cells_made"].get<int>(), 0) << "133 m on from the frame before: cells of its own";
}

// The exact reference traces each frame's plants and ground: a landscape's change with the eye.
TEST(Capture, ALandscapesReferenceFollowsItsPlantsAlongThePath) {
  const TempDir dir;
  const CommandResult r = run_ecoview({"capture", "--scene", "landscape", "--path", "landscape", "--fps", "1", "--frames", "3:5",
                                       "--size", "160x90", "--aov", "reference", "--out", dir.path().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* file : {"reference_00003.png", "reference_00004.png"}) {
    const Gray reference = load_gray(dir / file);
    const auto shadowed = std::count_if(reference.pixels.begin(), reference.pixels.end(), [](unsigned char v) { return v < 128; });
    EXPECT_GT(shadowed, 100) << file;
    EXPECT_LT(shadowed, static_cast<long>(reference.pixels.size()) - 100) << file;
  }
}

// A process killed between writing a frame and renaming it leaves its temporary file; the capture
// that renders the frame again removes it, and only it.
TEST(Capture, ARerunRemovesTheTemporaryFilesAKilledCaptureLeft) {
  const TempDir dir;
  for (const char* name : {"color_00001.png.tmp4242", "stats.json.tmp7", "color_00007.png.tmp5", "notes.txt"}) write_text(dir / name, "x");
  const CommandResult r = run_ecoview({"capture", "--scene", "courtyard", "--size", "64x36", "--frames", "0:2",
                                       "--stats", (dir / "stats.json").string(), "--out", dir.path().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(files_in(dir.path()),
            (std::vector<std::string>{"color_00000.png", "color_00001.png", "color_00007.png.tmp5", "notes.txt", "stats.json"}));
}

// Whether each output can be written is known before the first frame renders.
TEST(Capture, StatsThatCannotBeWrittenAreRefusedBeforeRendering) {
  const TempDir dir;
  const std::filesystem::path out = dir / "out";
  for (const std::string& stats : {out.string(), (out / ".").string(), std::string("/proc/ecoview-stats.json")}) {
    const CommandResult r = run_ecoview({"capture", "--scene", "courtyard", "--size", "64x36", "--stats", stats, "--out", out.string()});
    EXPECT_EQ(r.exit_code, 2) << stats << ": " << r.err;
    EXPECT_NE(r.err.find("--stats"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << stats << ": rendered before failing";
  }
}

// For timing alone: the figures of every frame and no image, and without --stats nothing to write.
TEST(Capture, AovNoneWritesTheFiguresOfEveryFrameAndNoImage) {
  const TempDir dir;
  const std::filesystem::path out = dir / "out", stats = dir / "stats.json";
  const CommandResult r = run_ecoview({"capture", "--scene", "courtyard", "--size", "64x36", "--frames", "0:2", "--aov", "none",
                                       "--stats", stats.string(), "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(read_bytes(stats)).size(), 2u);
  EXPECT_TRUE(files_in(out).empty());

  const CommandResult refused = run_ecoview({"capture", "--scene", "courtyard", "--size", "64x36", "--aov", "none", "--out", (dir / "o2").string()});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--aov none"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o2"));
}

// Libraries write their own lines (OpenMesh on a truncated binary PLY): they are folded into ours.
TEST(Capture, BadMeshFilesGiveOneLineWhateverTheLibrarySays) {
  const TempDir dir;
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n";
  write_text(dir / "truncated.ply", header + "property float z\nend_header\nabc");
  write_text(dir / "mistyped.ply", header + "property fdoat z\nend_header\n");
  write_text(dir / "empty.off", "");
  for (const char* mesh : {"truncated.ply", "mistyped.ply", "empty.off"}) {
    write_text(dir / "scene.json", R"({"camera": {"position": [0, 8, 12], "target": [0, 0, 0]},
      "lights": [{"type": "directional", "direction": [0.3, -1, 0.2]}], "objects": [{"type": "mesh", "file": ")" +
                                       std::string(mesh) + R"("}]})");
    const CommandResult r = run_ecoview({"capture", "--scene", (dir / "scene.json").string(), "--out", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(std::string("objects[0].file: ") + mesh), std::string::npos) << r.err;
  }
}

// A mesh whose references would make capture read /dev/zero forever or overflow its stack: each
// refused within seconds, in one line naming the mesh and the file it refers to.
TEST(Capture, AMeshReferringToADeviceOrAFolderOrNestedTooDeepIsRefusedAtOnce) {
  const TempDir dir;
  write_text(dir / "lamp.obj", "mtllib /dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write_text(dir / "lamp.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "/dev/zero", "byteLength": 36}]})");
  std::filesystem::create_directory(dir / "bark.png");
  write_text(dir / "tree.gltf", R"({"asset": {"version": "2.0"}, "images": [{"uri": "bark.png"}]})");
  std::string deep;  // an object in an object ... 100,000 levels: tinygltf's recursive reader overflows the stack
  for (int level = 0; level < 100000; ++level) deep += "{\"a\":";
  deep += "1" + std::string(100000, '}');
  write_text(dir / "deep.gltf", R"({"asset": {"version": "2.0"}, "extensions": {"deep": )" + deep + "}}");
  const std::map<std::string, std::string> expected = {
      {"lamp.obj", "objects[0].file: lamp.obj: line 1: mtllib: /dev/zero: not a regular file (a character device)"},
      {"lamp.gltf", "objects[0].file: lamp.gltf: refers to /dev/zero: not a regular file (a character device)"},
      {"tree.gltf", "objects[0].file: tree.gltf: refers to " + (dir / "bark.png").string() + ": not a regular file (a folder)"},
      {"deep.gltf", "objects[0].file: deep.gltf: JSON nested deeper than 256 levels"}};
  for (const auto& [mesh, message] : expected) {
    write_text(dir / "scene.json", R"({"camera": {"position": [0, 8, 12], "target": [0, 0, 0]},
      "lights": [{"type": "directional", "direction": [0.3, -1, 0.2]}], "objects": [{"type": "mesh", "file": ")" + mesh + R"("}]})");
    const auto start = std::chrono::steady_clock::now();
    const CommandResult r = run_ecoview({"capture", "--scene", (dir / "scene.json").string(), "--out", (dir / "out").string()});
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30)) << mesh;
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
}

TEST(CommandLine, UnknownCommandsAndOptionsAreNamedFirst) {
  CommandResult r = run_ecoview({"bogus"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown command 'bogus'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("capture, view, density, bench"), std::string::npos) << r.err;
  r = run_ecoview({});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a command is required"), std::string::npos) << r.err;
  for (const char* command : {"capture", "density", "bench"}) {
    r = run_ecoview({command, "--colour", "red"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--colour"), std::string::npos) << command << ": " << r.err;
    r = run_ecoview({command});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--out is required"), std::string::npos) << command << ": " << r.err;
  }
}

// Output names the system would refuse: a name longer than the file system takes (in a folder
// that is there, and below one that is not), and a folder inside a file. Every command with
// --out says so as bad input, one line naming the option, the path and the reason, before it
// loads a scene, and makes nothing.
TEST(CommandLine, OutputNamesTheSystemRefusesAreBadInputForEveryCommand) {
  const TempDir dir;
  write_text(dir / "file", "x");
  const std::string long_name(300, 'a');
  const std::vector<std::pair<std::string, std::string>> refused = {  // the path, and the reason
      {(dir / long_name).string(), "too long"},
      {(dir / "new" / long_name / "x").string(), "too long"},
      {(dir / "file" / "x").string(), "ot a"}};  // "not a folder", "Not a directory"
  const std::vector<std::vector<std::string>> commands = {{"capture", "--scene", "courtyard"}, {"view", "--scene", "courtyard"},
                                                          {"bench", "--quick"}, {"bench", "--quick", "--suite", "paper"},
                                                          {"density", "--quick", "--scene", "courtyard"}};
  for (const std::vector<std::string>& command : commands) {
    for (const auto& [out, reason] : refused) {
      std::vector<std::string> args = command;
      args.insert(args.end(), {"--out", out});
      const CommandResult r = run_shell("unset DISPLAY WAYLAND_DISPLAY; ecoview " + [&] {
        std::string quoted;
        for (const std::string& a : args) quoted += shell_quote(a) + " ";
        return quoted;
      }());
      EXPECT_EQ(r.exit_code, 2) << command[0] << " " << out << ": " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_NE(r.err.find("--out: " + out), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
      EXPECT_EQ(r.out.find("scene:"), std::string::npos) << "loaded a scene first: " << r.out;
    }
  }
  // --stats: the same, and a name the folder takes whose temporary name (the name and ".tmp" and
  // the process id) it would not.
  const std::string nearly_long = std::string(250, 'a') + ".json";
  write_text(dir / nearly_long, "x");
  std::filesystem::remove(dir / nearly_long);
  for (const auto& [stats, reason] : {refused[0], refused[1], refused[2], std::pair{(dir / nearly_long).string(), std::string("too long")}}) {
    const CommandResult r = run_ecoview({"capture", "--scene", "courtyard", "--size", "64x36", "--stats", stats,
                                         "--out", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << stats << ": " << r.err;
    EXPECT_NE(r.err.find("--stats: " + stats), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
  }
  EXPECT_EQ(files_in(dir.path()), std::vector<std::string>{"file"});
}

// `ecoview scenes` has a line for each scene and each camera path in data/ (the binary embeds
// them): the name, whether it is a scene, a path or both, and a scene's lights, objects and comment.
TEST(Scenes, ListsEveryShippedSceneAndPathWithWhatItHolds) {
  std::map<std::string, std::pair<bool, bool>> shipped;  // scene, path
  for (const char* folder : {"scenes", "paths"}) {
    for (const std::string& file : files_in(source_dir() / "data" / folder)) {
      if (file.size() <= 5 || file.substr(file.size() - 5) != ".json") continue;
      auto& [scene, path] = shipped[file.substr(0, file.size() - 5)];
      (std::string(folder) == "scenes" ? scene : path) = true;
    }
  }
  ASSERT_GE(shipped.size(), 2u);
  const CommandResult r = run_ecoview({"scenes"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, std::string> listed;  // name: the rest of its line
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_match(line, m, std::regex(R"(  (\S+) +(.*))"))) listed[m[1]] = m[2];
  }
  ASSERT_EQ(listed.size(), shipped.size()) << r.out;
  for (const auto& [name, kinds] : shipped) {
    const auto& [scene, path] = kinds;
    ASSERT_TRUE(listed.count(name)) << name << " not in " << r.out;
    const std::string& line = listed[name];
    EXPECT_EQ(line.rfind(scene && path ? "scene and path" : scene ? "scene " : "path ", 0), 0u) << name << ": " << line;
    if (!scene) continue;
    const nlohmann::json json = nlohmann::json::parse(read_bytes(source_dir() / "data" / "scenes" / (name + ".json")));
    for (const char* counted : {"light", "object"}) {
      const std::string count = std::to_string(json[std::string(counted) + "s"].size());
      EXPECT_TRUE(std::regex_search(line, std::regex("\\b" + count + " " + counted))) << line;
    }
    if (json.contains("comment")) {
      EXPECT_NE(line.find(json["comment"].get<std::string>()), std::string::npos) << line;
    }
  }
}

// The commit is the one the binary was built from: one of this repository's (when it is a git
// checkout), "-dirty" after it when the tree had changes.
TEST(CommandLine, VersionGivesTheVersionAndTheCommit) {
  const CommandResult r = run_ecoview({"--version"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_match(r.out, m, std::regex(R"(ecoview \d+\.\d+(\.\d+)? \(git ([0-9a-f]{7,40}|unknown)(-dirty)?\)\n)"))) << r.out;
  if (m[2] == "unknown") return;
  const CommandResult known = run_shell("git -C " + shell_quote(source_dir().string()) + " cat-file -e " + m[2].str() + "^{commit}");
  EXPECT_EQ(known.exit_code, 0) << m[2] << " is not a commit of " << source_dir();
}

// The bundle for a machine with a GPU driver: the binary runs from it without this machine's
// libraries beyond glibc, and it holds no GL driver (no Mesa: a GPU machine brings its own).
TEST(GpuBundle, RunsOnItsOwnLibrariesAndHoldsNoDriver) {
  const TempDir dir;
  const std::string bundle = (dir / "bundle").string();
  const CommandResult made = run_shell("ECOVIEW_BINARY=\"$ecoview_binary\" " + shell_quote((source_dir() / "scripts/gpu_bundle.sh").string()) +
                                       " " + shell_quote(bundle));
  ASSERT_EQ(made.exit_code, 0) << made.err;
  std::uintmax_t bytes = 0;
  for (const std::filesystem::directory_entry& e : std::filesystem::recursive_directory_iterator(bundle)) bytes += e.is_regular_file() ? e.file_size() : 0;
  EXPECT_LT(bytes, std::uintmax_t{60} << 20);

  const CommandResult version = run_shell("env -i PATH=/usr/bin:/bin " + shell_quote(bundle + "/ecoview") + " --version");
  EXPECT_EQ(version.exit_code, 0) << version.err;
  EXPECT_EQ(version.out.rfind("ecoview ", 0), 0u) << version.out;
  // Where the loader finds each library with the bundle's folder first.
  const CommandResult libraries = run_shell("LD_LIBRARY_PATH=" + shell_quote(bundle + "/lib") + " ldd " + shell_quote(bundle + "/bin/ecoview"));
  ASSERT_EQ(libraries.exit_code, 0) << libraries.err;
  std::istringstream lines(libraries.out);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, std::regex(R"((\S+) => (\S+))"))) continue;
    const std::string name = m[1], path = m[2];
    EXPECT_EQ(name.find("Mesa"), std::string::npos) << line;
    EXPECT_EQ(name.find("LLVM"), std::string::npos) << line;
    EXPECT_EQ(name.find("gallium"), std::string::npos) << line;
    const bool glibc = std::regex_match(name, std::regex(R"((libc|libm|libdl|libpthread|librt)\.so\.\d+)"));
    if (!glibc) {
      EXPECT_EQ(path.rfind(bundle + "/lib/", 0), 0u) << line;
    }
  }
}

struct BadInput {
  const char* name;
  std::string scene;               // written to bad.json when not empty
  std::vector<std::string> args;   // extra arguments
  std::vector<std::string> expect; // parts of the message
};

class CaptureBadInput : public testing::TestWithParam<BadInput> {};

const std::string good_start = R"({"camera": {"position": [0, 8, 12], "target": [0, 0, 0]},
  "lights": [{"type": "directional", "direction": [0.3, -1, 0.2]}],
  "objects": [)";

TEST_P(CaptureBadInput, ExitsTwoWithOneLineAndWritesNothing) {
  const BadInput& c = GetParam();
  const TempDir dir;
  std::vector<std::string> args = {"capture", "--out", (dir / "out").string()};
  if (!c.scene.empty()) {
    write_text(dir / "bad.json", c.scene);
    args.insert(args.end(), {"--scene", (dir / "bad.json").string()});
  }
  args.insert(args.end(), c.args.begin(), c.args.end());
  const CommandResult r = run_ecoview(args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const std::string& part : c.expect) EXPECT_NE(r.err.find(part), std::string::npos) << "'" << part << "' not in " << r.err;
  EXPECT_TRUE(files_in(dir / "out").empty());
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CaptureBadInput,
    testing::Values(
        BadInput{"invalid_json", good_start + "{\"type\": \"plane\" \"center\": [0,0,0]}]}", {}, {"bad.json:3:", "invalid JSON"}},
        BadInput{"unknown_object", good_start + R"({"type": "torus"}]})", {}, {"bad.json", "objects[0].type"}},
        BadInput{"missing_mesh", good_start + R"({"type": "mesh", "file": "gone.obj"}]})", {}, {"bad.json", "objects[0].file", "gone.obj"}},
        BadInput{"wrong_length", good_start + R"({"type": "box", "min": [0, 0], "max": [1, 1, 1]}]})", {}, {"bad.json", "objects[0].min"}},
        BadInput{"nan", good_start + R"({"type": "sphere", "center": [0, NaN, 0], "radius": 1}]})", {}, {"bad.json:3:"}},
        BadInput{"infinity", good_start + R"({"type": "sphere", "center": [0, 1e400, 0], "radius": 1}]})", {}, {"bad.json:3:"}},
        BadInput{"zero_light_direction", R"({"camera": {"position": [0, 8, 12], "target": [0, 0, 0]},
          "lights": [{"type": "directional", "direction": [0, 0, 0]}], "objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 1}]})",
                 {}, {"bad.json", "lights[0].direction"}},
        BadInput{"truncated", good_start, {}, {"bad.json:", "invalid JSON"}},
        BadInput{"nested_too_deep", "{\"comment\": " + std::string(100000, '[') + std::string(100000, ']') + "}", {},
                 {"bad.json:1:268: invalid JSON: nested deeper than 256 levels"}},
        BadInput{"wrong_type", good_start + R"({"type": "sphere", "center": [0, 1, 0], "radius": [1]}]})", {}, {"bad.json", "objects[0].radius"}},
        BadInput{"size_zero", "", {"--size", "0x0"}, {"--size"}},
        BadInput{"frames_backwards", "", {"--frames", "5:2"}, {"--frames"}},
        BadInput{"unknown_method", "", {"--method", "magic"}, {"--method"}},
        BadInput{"shadowmap_without_map", "", {"--method", "volumes", "--aov", "color,shadowmap"}, {"--aov", "volumes"}},
        BadInput{"unknown_aov", "", {"--aov", "color,normals"}, {"--aov", "normals"}},
        BadInput{"aov_format", "", {"--aov-format", "tiff"}, {"--aov-format", "png or exr", "'tiff'"}},
        BadInput{"video_of_odd_size", "", {"--size", "161x90", "--video", "v.mp4"}, {"--video", "even width and height", "161x90"}},
        BadInput{"video_not_mp4", "", {"--video", "v.mkv"}, {"--video", "FILE.mp4", "v.mkv"}},
        BadInput{"video_without_color", "", {"--aov", "shadow", "--video", "v.mp4"}, {"--video", "add color to --aov"}},
        BadInput{"unknown_scene", "", {"--scene", "no-such-scene"}, {"no-such-scene", "courtyard"}},
        BadInput{"scene_is_a_device", "", {"--scene", "/dev/zero"}, {"/dev/zero: not a regular file (a character device)"}},
        BadInput{"path_is_a_device", "", {"--path", "/dev/zero"}, {"/dev/zero: not a regular file (a character device)"}},
        BadInput{"light_index", "", {"--scene", "courtyard", "--light", "7"}, {"--light"}},
        BadInput{"huge_shadow_map", "", {"--shadow-size", "100000"}, {"--shadow-size"}},
        BadInput{"unknown_option", "", {"--colour"}, {"--colour"}},
        BadInput{"memory_budget", good_start + R"({"type": "ecosystem", "size": [900, 900], "plants": [{"species": "oak", "count": 30000000}]}]})",
                 {"--memory-budget", "2"}, {"bad.json", "objects[0]", "memory budget of 2.00 GiB"}},
        BadInput{"plant_pool", "", {"--plant-pool", "0"}, {"--plant-pool", "between 1 and"}},
        BadInput{"landscape_ground_step", good_start + R"({"type": "landscape", "size": [500, 500], "ground_step": 0,
                 "layers": [{"cell_size": 10, "density": 0.1, "radius": 50, "species": [{"species": "oak"}]}]}]})",
                 {}, {"bad.json", "objects[0].ground_step"}},
        BadInput{"bad_species", good_start + R"({"type": "ecosystem", "size": [90, 90], "plants": [{"species": "kelp", "count": 3}]}]})",
                 {}, {"bad.json", "objects[0].plants[0].species", "kelp"}},
        BadInput{"bad_crowd", good_start + R"({"type": "crowd", "count": 10, "center": [0, 0, 0], "size": [-1, 4]}]})",
                 {}, {"bad.json", "objects[0].size"}},
        BadInput{"house_row_budget", good_start + R"({"type": "houses", "from": [-1000000, 0], "to": [1000000, 0]}]})",
                 {}, {"bad.json", "objects[0]", "memory budget"}},
        // A string from the file with a line break in it: still one line, the break escaped.
        BadInput{"newline_in_a_value", good_start + R"({"type": "laser\nsecond line"}]})", {}, {"objects[0].type", "laser\\nsecond"}},
        BadInput{"stats_is_a_folder", "", {"--stats", "/"}, {"--stats", "is a folder"}},
        BadInput{"negative_bias", "", {"--bias-slope", "-1"}, {"--bias-slope", "between 0 and"}},
        BadInput{"bias_not_a_number", "", {"--bias-constant", "nan"}, {"--bias-constant", "between 0 and"}},
        BadInput{"depth_of_8_bits", "", {"--shadow-depth", "8"}, {"--shadow-depth", "16, 24 or 32f", "'8'"}}),
    [](const testing::TestParamInfo<BadInput>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace ecoview::test
