#pragma once
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace ecoview {

// Writes to a temporary name beside `path` (`path` + ".tmp" + the process id) and renames it
// into place, so `path` is either absent or complete. Throws RuntimeFailure naming the file.
// One file is in flight at a time; a SIGINT or SIGTERM removes it (remove_temporary_on_signals).
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// The bytes of a file the user named (a scene, a path, an earlier run's results): as
// pointgen::read_input_file reads it, a missing or refused file being bad input (InputError).
std::string read_named_file(const std::filesystem::path& path);

// A file written over a long time by a library that opens it by name (a video, frame by frame): it
// is made at temporary() (`path` + ".tmp" + the process id) and renamed to `path` by finish(), so
// `path` is either absent or complete. Destroyed unfinished, or on SIGINT or SIGTERM
// (remove_temporary_on_signals), the temporary file is removed. One is open at a time.
class FileInProgress {
 public:
  explicit FileInProgress(std::filesystem::path path);
  ~FileInProgress();
  FileInProgress(const FileInProgress&) = delete;
  FileInProgress& operator=(const FileInProgress&) = delete;

  const std::filesystem::path& temporary() const { return temporary_; }
  // Renames the temporary file into place; throws RuntimeFailure naming the file.
  void finish();

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  bool finished_ = false;
};

// From now on SIGINT and SIGTERM remove the temporary file in flight, and that of the
// FileInProgress open, before the process ends as the signal would end it.
void remove_temporary_on_signals();

// Removes the temporary files write_file_atomically would leave in `folder` for the files named
// in `names` (by any process, killed between writing and renaming). Returns how many it removed.
int remove_stale_temporaries(const std::filesystem::path& folder, const std::set<std::string>& names);

// Whether a new file can be made in `folder` (tried with a temporary file, then removed);
// the reason it cannot otherwise.
std::optional<std::string> cannot_write_in(const std::filesystem::path& folder);

// Why the system would refuse to make `path`, a folder, and the folders above it that are not
// there yet: a part of it that cannot be looked up ("Permission denied", "Not a directory") or a
// name longer than its file system takes. Nothing where it would make it.
std::optional<std::string> refused_name(const std::filesystem::path& path);
// The same for a file write_file_atomically writes: its temporary name is longer.
std::optional<std::string> refused_file_name(const std::filesystem::path& path);

}  // namespace ecoview
