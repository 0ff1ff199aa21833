// Files written whole or not at all: a signal during a write leaves no temporary file, a rerun
// removes those a killed process left.
#include "app/file_io.hpp"
#include "test_support.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

// The child writes `frame.png` through a FIFO put where its temporary file goes, so the write
// blocks with the temporary file in flight until this process reads; then it gets SIGTERM.
TEST(FileIo, ASignalDuringAWriteRemovesTheTemporaryFile) {
  const TempDir dir;
  int go[2];
  ASSERT_EQ(::pipe(go), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporary_on_signals();
    char byte = 0;
    if (::read(go[0], &byte, 1) != 1) std::_Exit(10);
    try {
      write_file_atomically(dir / "frame.png", std::string(1 << 20, 'x'));  // more than a pipe holds
    } catch (...) {
      std::_Exit(11);
    }
    std::_Exit(12);
  }
  struct Reaper {  // an assertion failing below must not leave the child waiting
    pid_t pid;
    int status = 0;
    bool reaped = false;
    void reap() { reaped = ::waitpid(pid, &status, 0) == pid; }
    ~Reaper() {
      if (reaped) return;
      ::kill(pid, SIGKILL);
      reap();
    }
  } child_process{child};
  const std::filesystem::path temporary = dir / ("frame.png.tmp" + std::to_string(child));
  ASSERT_EQ(::mkfifo(temporary.c_str(), 0600), 0);
  ASSERT_EQ(::write(go[1], "g", 1), 1);
  const int fifo = ::open(temporary.c_str(), O_RDONLY);  // returns once the child has opened it
  ASSERT_GE(fifo, 0);
  char some[4096];
  ASSERT_GT(::read(fifo, some, sizeof some), 0);  // the child is writing
  ::kill(child, SIGTERM);
  child_process.reap();
  ::close(fifo);
  const int status = child_process.status;
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
  EXPECT_TRUE(files_in(dir.path()).empty()) << "left behind: " << files_in(dir.path()).front();
}

TEST(FileIo, StaleTemporariesOfTheNamedFilesAreRemovedAndNothingElse) {
  const TempDir dir;
  for (const char* name : {"color_00001.png.tmp4242", "color_00001.png.tmp17", "shadow_00001.png.tmp9", "color_00002.png.tmp5",
                           "color_00001.png.tmpx", "color_00001.png", "notes.tmp3"}) {
    write_text(dir / name, "x");
  }
  EXPECT_EQ(remove_stale_temporaries(dir.path(), {"color_00001.png", "shadow_00001.png"}), 3);
  EXPECT_EQ(files_in(dir.path()),
            (std::vector<std::string>{"color_00001.png", "color_00001.png.tmpx", "color_00002.png.tmp5", "notes.tmp3"}));
}

TEST(FileIo, AFolderThatCannotTakeAFileIsSaidSo) {
  const TempDir dir;
  EXPECT_FALSE(cannot_write_in(dir.path()));
  EXPECT_TRUE(files_in(dir.path()).empty()) << "the probe stays";
  EXPECT_TRUE(cannot_write_in("/proc"));
  EXPECT_TRUE(cannot_write_in(dir / "missing"));
}

// A file written over a long time (a video) is at its own name only once finished; left
// unfinished, its temporary file goes.
TEST(FileIo, AFileInProgressLandsWhenFinishedAndVanishesOtherwise) {
  const TempDir dir;
  {
    FileInProgress video(dir / "done.mp4");
    write_text(video.temporary(), "frames");
    EXPECT_EQ(files_in(dir.path()), std::vector<std::string>{"done.mp4.tmp" + std::to_string(::getpid())});
    video.finish();
  }
  {
    FileInProgress video(dir / "failed.mp4");
    write_text(video.temporary(), "half");
  }
  EXPECT_EQ(files_in(dir.path()), std::vector<std::string>{"done.mp4"});
  EXPECT_EQ(read_bytes(dir / "done.mp4"), "frames");
}

// A process stopped with a file in progress takes its temporary file with it.
TEST(FileIo, ASignalRemovesTheFileInProgress) {
  const TempDir dir;
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporary_on_signals();
    FileInProgress video(dir / "video.mp4");
    write_text(video.temporary(), "frames");
    if (::write(ready[1], "r", 1) != 1) std::_Exit(10);
    ::pause();
    std::_Exit(11);
  }
  ::close(ready[1]);  // a child that ends early ends the read below
  char byte = 0;
  const bool child_ready = ::read(ready[0], &byte, 1) == 1;
  ::kill(child, SIGINT);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(child_ready);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << "status " << status;
  EXPECT_TRUE(files_in(dir.path()).empty()) << "left behind: " << files_in(dir.path()).front();
}

}  // namespace
}  // namespace ecoview::test
