#include "app/huge_pages.hpp"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include <unistd.h>

namespace ecoview {

// Large scenes fill large buffers: a 10^7-plant ecosystem's tables and placement grid, and on
// llvmpipe the GPU's buffers, which the driver clears in host memory. Touched a 4 KiB page at a
// time they fault for seconds (on a virtual machine, most of the load). glibc's malloc advises
// huge pages for its mappings when its tunable says so, and it reads tunables only at the start.
void run_with_huge_pages(char** argv) {
  constexpr const char* tunable = "glibc.malloc.hugetlb=1";
  std::string mode;
  std::getline(std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"), mode);
  if (mode.find("[madvise]") == std::string::npos) return;  // always, never, or no such kernel
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) return;  // set already, by us or the user
  // Started through the dynamic loader (ld-linux ... ecoview), this process's file is the loader.
  char self[4096] = {};
  if (readlink("/proc/self/exe", self, sizeof self - 1) <= 0 || std::strstr(self, "/ld-")) return;
  const std::string wanted = tunables && *tunables ? std::string(tunables) + ":" + tunable : tunable;
  if (setenv("GLIBC_TUNABLES", wanted.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only where it failed
}

}  // namespace ecoview
