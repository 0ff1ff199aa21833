#pragma once
#include <stdexcept>
#include <string>

namespace ecoview {

// Bad input from the user: exit code 2. what() is the one line printed, naming the file (or
// command-line option) and the field: "scene.json: objects[2].min: expected 3 numbers".
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The machine cannot do what was asked (no GL context, a file cannot be written): exit code 1.
// what() says what failed and what to try.
class RuntimeFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ecoview
