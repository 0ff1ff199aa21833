#include "app/file_io.hpp"

#include "app/errors.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <mutex>

namespace ecoview {
namespace {

const std::string temporary_suffix = ".tmp";

std::filesystem::path temporary_name(const std::filesystem::path& path) {
  std::filesystem::path temporary = path;
  temporary += temporary_suffix + std::to_string(::getpid());
  return temporary;
}

// The temporary file in flight, for the signal handler: a fixed buffer it may read, and a flag
// set only while the name in it is whole.
std::mutex one_write_at_a_time;
char in_flight_name[4096];
volatile std::sig_atomic_t in_flight = 0;

extern "C" void remove_in_flight_and_end(int signal) {
  if (in_flight) ::unlink(in_flight_name);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
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
  const std::string& name = temporary.native();
  const bool signal_removes = name.size() < sizeof in_flight_name;
  if (signal_removes) {
    std::memcpy(in_flight_name, name.c_str(), name.size() + 1);
    in_flight = 1;
  }
  struct Landed {  // the flag is cleared however this ends
    ~Landed() { in_flight = 0; }
  } landed;
  write_temporary(temporary, path, bytes);
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    const std::string reason = ec.message();
    std::filesystem::remove(temporary, ec);
    throw RuntimeFailure(path.string() + ": cannot rename into place (" + reason + ")");
  }
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

}  // namespace ecoview
