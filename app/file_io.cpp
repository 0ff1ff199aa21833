#include "app/file_io.hpp"

#include "app/errors.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <sstream>

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

std::optional<std::string> read_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return std::move(bytes).str();
}

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
