#pragma once
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace ecoview {

// Parses JSON text; a syntax error, or nesting deeper than pointgen::max_json_nesting, throws
// InputError "file:line:column: ...".
nlohmann::json parse_json(const std::string& text, const std::string& file);

// A value inside a parsed JSON document that knows its file and path ("objects[2].min"), so every
// problem with it becomes an InputError naming both. Every number read is checked finite and
// within the given range.
class JsonField {
 public:
  JsonField(const nlohmann::json& value, std::string file, std::string path = "");

  [[noreturn]] void fail(const std::string& problem) const;

  // Objects.
  bool has(const char* key) const;
  JsonField operator[](const char* key) const;  // required
  std::optional<JsonField> optional(const char* key) const;
  // Fails on any key not in `allowed`, which catches misspelt keys.
  void only_keys(std::initializer_list<const char*> allowed) const;

  // Arrays.
  std::vector<JsonField> items(std::size_t min_count = 0) const;

  // Leaves.
  bool is_string() const { return value_->is_string(); }
  std::string string() const;
  bool boolean() const;
  double number(double min, double max) const;
  float number_f(double min, double max) const { return static_cast<float>(number(min, max)); }
  int integer(int min, int max) const;
  // An array of exactly N numbers, each within [min, max].
  std::vector<double> numbers(std::size_t count, double min, double max) const;
  // Two numbers within [min, max], the smaller first: a range such as a scale's or an altitude's.
  glm::vec2 range(double min, double max) const;
  glm::vec3 vec3(double limit = max_coordinate) const;
  glm::vec3 color() const;  // three numbers in 0..1

  // Coordinates are metres; beyond this a float cannot hold centimetres.
  static constexpr double max_coordinate = 1e6;

 private:
  std::string child_path(const std::string& key) const;
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

}  // namespace ecoview
