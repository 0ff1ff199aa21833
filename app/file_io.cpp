#include "app/file_io.hpp"

#include "app/errors.hpp"
#include "pointgen/file_error.hpp"
#include "pointgen/input_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>

namespace ecoview {
namespace {

const std::string temporary_suffix = ".tmp";

std::filesystem::path temporary_name(const std::filesystem::path& path) {
  std::filesystem::path temporary = path;
  temporary += temporary_suffix + std::to_string(::getpid());
  return temporary;
}

// A temporary file's name for the signal handler: a fixed buffer it may read, and a flag set only
// while the name in it is whole.
struct SignalRemovedName {
  char name[4096];
  volatile std::sig_atomic_t held = 0;

  // A name too long for the buffer is not held: remove_stale_temporaries takes its file.
  void hold(const std::filesystem::path& path) {
    const std::string& native = path.native();
    if (native.size() >= sizeof name) return;
    std::memcpy(name, native.c_str(), native.size() + 1);
    std::atomic_signal_fence(std::memory_order_release);  // the name is whole before the flag says so
    held = 1;
  }
  void release() { held = 0; }
  void remove() const {
    if (held) ::unlink(name);
  }
};

// The file write_file_atomically has in flight, and the FileInProgress open.
std::mutex one_write_at_a_time;
SignalRemovedName in_flight;
SignalRemovedName in_progress;

extern "C" void remove_in_flight_and_end(int signal) {
  in_flight.remove();
  in_progress.remove();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void rename_into_place(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    const std::string reason = ec.message();
    std::filesystem::remove(temporary, ec);
    throw RuntimeFailure(path.string() + ": cannot rename into place (" + reason + ")");
  }
}

void write_temporary(const std::filesystem::path& temporary, const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.flush();
  if (!out) {
    const std::string reason = std::strerror(errno);
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw RuntimeFailure(path.string() + ": cannot write (" + reason + "); check the folder and free space");
  }
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  const std::lock_guard lock(one_write_at_a_time);
  const std::filesystem::path temporary = temporary_name(path);
  in_flight.hold(temporary);
  struct Landed {  // the flag is cleared however this ends
    ~Landed() { in_flight.release(); }
  } landed;
  write_temporary(temporary, path, bytes);
  rename_into_place(temporary, path);
}

std::string read_named_file(const std::filesystem::path& path) {
  std::optional<std::string> text;
  try {
    text = pointgen::read_input_file(path);
  } catch (const pointgen::FileError& e) {
    throw InputError(e.what());
  }
  if (!text) throw InputError(path.string() + ": no such file");
  return std::move(*text);
}

FileInProgress::FileInProgress(std::filesystem::path path) : path_(std::move(path)), temporary_(temporary_name(path_)) {
  if (in_progress.held) throw std::logic_error("one FileInProgress at a time");
  in_progress.hold(temporary_);
}

// The file goes before its name is released, so that a signal in between still removes it.
FileInProgress::~FileInProgress() {
  if (!finished_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
  in_progress.release();
}

void FileInProgress::finish() {
  rename_into_place(temporary_, path_);
  finished_ = true;
  in_progress.release();
}

void remove_temporary_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_in_flight_and_end;
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGINT, SIGTERM}) sigaction(signal, &action, nullptr);
}

int remove_stale_temporaries(const std::filesystem::path& folder, const std::set<std::string>& names) {
  std::error_code ec;
  int removed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string file = entry.path().filename().string();
    const std::size_t suffix = file.rfind(temporary_suffix);
    if (suffix == std::string::npos || !names.count(file.substr(0, suffix))) continue;
    const std::string pid = file.substr(suffix + temporary_suffix.size());
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::error_code ignored;
    if (entry.is_regular_file(ignored) && std::filesystem::remove(entry.path(), ignored)) ++removed;
  }
  return removed;
}

std::optional<std::string> cannot_write_in(const std::filesystem::path& folder) {
  const std::filesystem::path probe = temporary_name(folder / ".ecoview-write-check");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) return std::string(std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
  return std::nullopt;
}

// refused_name, where the last name is to take `suffix` more characters.
static std::optional<std::string> refused_name_with(const std::filesystem::path& path, std::size_t suffix) {
  namespace fs = std::filesystem;
  const fs::path absolute = fs::absolute(path).lexically_normal();
  if (absolute.native().size() + suffix >= PATH_MAX) {
    return "File name too long (the path has " + std::to_string(absolute.native().size()) + " characters, at most " +
           std::to_string(PATH_MAX - 1 - suffix) + ")";
  }
  // The parts there are: the system says what it will not look up. The first that is not there
  // ends them; the file system of the folder above takes the rest.
  fs::path existing;
  auto part = absolute.begin();
  for (; part != absolute.end(); ++part) {
    std::error_code ec;
    static_cast<void>(fs::status(existing / *part, ec));  // the error code is the answer
    if (ec == std::errc::no_such_file_or_directory) break;
    if (ec) return ec.message();
    existing /= *part;
  }
  const long name_max = ::pathconf(existing.c_str(), _PC_NAME_MAX);
  for (; part != absolute.end(); ++part) {
    const std::size_t length = part->native().size() + (std::next(part) == absolute.end() ? suffix : 0);
    if (name_max > 0 && length > static_cast<std::size_t>(name_max)) {
      return "File name too long (" + std::to_string(part->native().size()) + " characters, at most " +
             std::to_string(static_cast<std::size_t>(name_max) - length + part->native().size()) + " there)";
    }
  }
  return std::nullopt;
}

std::optional<std::string> refused_name(const std::filesystem::path& path) { return refused_name_with(path, 0); }

std::optional<std::string> refused_file_name(const std::filesystem::path& path) {
  return refused_name_with(path, temporary_name(path).filename().native().size() - path.filename().native().size());
}

}  // namespace ecoview
