#include "pointgen/input_file.hpp"

#include "pointgen/file_error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace pointgen {
namespace {

std::string kind_of_file(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a pipe";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a plain file";
}

[[noreturn]] void refuse_irregular(const std::string& path, mode_t mode) {
  throw FileError(path, "not a regular file (" + kind_of_file(mode) + ")");
}

[[noreturn]] void refuse_unreadable(const std::string& path) {
  throw FileError(path, std::string("cannot be read (") + std::strerror(errno) + ")");
}

// Closes the descriptor however reading ends.
struct OpenFile {
  int fd;
  ~OpenFile() {
    if (fd >= 0) ::close(fd);
  }
};

// Up to `size` bytes from the start of the open file: fewer where it shrank since it was measured.
std::string read_up_to(const OpenFile& file, const std::string& name, std::size_t size) {
  std::string bytes(size, '\0');
  std::size_t done = 0;
  while (done < size) {
    const ssize_t got = ::read(file.fd, bytes.data() + done, size - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) refuse_unreadable(name);
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace

std::optional<std::string> read_input_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  struct stat status {};
  if (::stat(name.c_str(), &status) != 0) {
    if (errno == ENOENT || errno == ENOTDIR) return std::nullopt;
    refuse_unreadable(name);
  }
  // Checked before opening too: opening a device or a pipe can block or have effects of its own.
  if (!S_ISREG(status.st_mode)) refuse_irregular(name, status.st_mode);
  const OpenFile file{::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0 || ::fstat(file.fd, &status) != 0) refuse_unreadable(name);
  if (!S_ISREG(status.st_mode)) refuse_irregular(name, status.st_mode);  // replaced since the first look
  if (static_cast<std::uint64_t>(status.st_size) > max_input_file_bytes) {
    throw FileError(name, "is " + std::to_string(status.st_size) + " bytes, more than the 2 GiB (2^31 - 1 bytes) ecoview reads from one file");
  }
  return read_up_to(file, name, static_cast<std::size_t>(status.st_size));
}

}  // namespace pointgen
