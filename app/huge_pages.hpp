#pragma once

namespace ecoview {

// Runs this program again, from its start, with glibc's malloc advising transparent huge pages for
// the memory it maps, where the kernel gives them only on advice and that tunable is not set yet;
// otherwise, or where that fails, returns and the program goes on as it is. `argv` as main has it.
void run_with_huge_pages(char** argv);

}  // namespace ecoview
