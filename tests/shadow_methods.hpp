#pragma once
#include "shadow/techniques.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace ecoview::test {

// Every method of the table that draws shadows: one added there is tested with no more lines.
inline std::vector<shadow::Method> methods_with_shadows() {
  std::vector<shadow::Method> methods;
  for (const shadow::Technique& t : shadow::techniques()) {
    if (t.lookup != shadow::Lookup::none) methods.push_back(t.method);
  }
  return methods;
}

// A method's name as part of a test's name, which must be an identifier (`psm+silhouette`).
inline std::string test_name(shadow::Method method) {
  std::string name = shadow::technique(method).name;
  std::replace(name.begin(), name.end(), '+', '_');
  return name;
}

}  // namespace ecoview::test
