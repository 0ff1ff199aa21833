#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

// Helpers for tests that run the ecoview binary or need files.
namespace ecoview::test {

// A fresh empty folder under the system's temporary folder, removed with the object.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

void write_text(const std::filesystem::path& path, const std::string& text);
std::string read_bytes(const std::filesystem::path& path);
// Names of the files in a folder, sorted; empty if the folder does not exist.
std::vector<std::string> files_in(const std::filesystem::path& folder);

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};
// Runs the ecoview binary built with these tests.
CommandResult run_ecoview(const std::vector<std::string>& args);
// Runs a /bin/sh script; `ecoview` in it runs the binary built with these tests, whose path is
// $ecoview_binary.
CommandResult run_shell(const std::string& script);
// `s` quoted for /bin/sh.
std::string shell_quote(const std::string& s);

// A PNG's pixels as stb_image (a decoder independent of ecoview's encoder) reads them, `channels`
// 8-bit samples each; empty where the file cannot be read.
struct PngImage {
  int width = 0, height = 0;
  std::vector<unsigned char> samples;
};
PngImage load_png(const std::filesystem::path& file, int channels);

// A scene file's plant object: `count` plants of `species` on the ground in rows of `per_row`,
// from (x0, z0), `dx` apart along x and `dz` from row to row.
std::string plant_grid_json(const std::string& species, int count, int per_row, float x0, float dx, float z0, float dz);

// The repository's root folder, and the shared test data beside it (which a user's clone lacks).
std::filesystem::path source_dir();
std::filesystem::path shared_testdata_dir();

}  // namespace ecoview::test
