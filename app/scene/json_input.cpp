#include "app/scene/json_input.hpp"

#include "app/errors.hpp"
#include "pointgen/json_nesting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ecoview {
namespace {

std::string type_name(const nlohmann::json& v) {
  return v.is_number() ? "a number" : v.is_string() ? "a string" : v.is_array() ? "an array"
       : v.is_object() ? "an object" : v.is_boolean() ? "a boolean" : "null";
}

std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// "line:column" of a byte offset into text, both from 1.
std::string position(const std::string& text, std::size_t byte) {
  byte = std::min(byte, text.size());
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(byte), '\n');
  const std::size_t line_start = byte == 0 ? std::string::npos : text.rfind('\n', byte - 1);
  const std::size_t column = line_start == std::string::npos ? byte + 1 : byte - line_start;
  return std::to_string(line) + ":" + std::to_string(column);
}

// The first place `needle` occurs in JSON text outside string literals.
std::size_t find_outside_strings(const std::string& text, const std::string& needle) {
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (in_string) {
      if (text[i] == '\\') ++i;
      else if (text[i] == '"') in_string = false;
    } else if (text[i] == '"') {
      in_string = true;
    } else if (text.compare(i, needle.size(), needle) == 0) {
      return i;
    }
  }
  return std::string::npos;
}

}  // namespace

nlohmann::json parse_json(const std::string& text, const std::string& file) {
  if (const std::optional<std::size_t> at = pointgen::json_nests_too_deep(text)) {
    throw InputError(file + ":" + position(text, *at) + ": invalid JSON: nested deeper than " +
                     std::to_string(pointgen::max_json_nesting) + " levels");
  }
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    std::string reason = e.what();
    const std::size_t colon = reason.find(": ", reason.find("parse error"));
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    throw InputError(file + ":" + position(text, e.byte == 0 ? 0 : e.byte - 1) + ": invalid JSON: " + reason);
  } catch (const nlohmann::json::exception& e) {
    // Number overflow ("1e999") carries no position; find the literal the message quotes.
    const std::string reason = e.what();
    const std::size_t open = reason.find('\'');
    const std::size_t close = reason.find('\'', open + 1);
    const std::size_t at = open == std::string::npos || close == std::string::npos
                               ? std::string::npos
                               : find_outside_strings(text, reason.substr(open + 1, close - open - 1));
    throw InputError(file + (at == std::string::npos ? "" : ":" + position(text, at)) +
                     ": invalid JSON: " + reason.substr(reason.find(']') + 2));
  }
}

JsonField::JsonField(const nlohmann::json& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

void JsonField::fail(const std::string& problem) const {
  throw InputError(file_ + ": " + (path_.empty() ? std::string("top level") : path_) + ": " + problem);
}

std::string JsonField::child_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

bool JsonField::has(const char* key) const { return value_->is_object() && value_->contains(key); }

JsonField JsonField::operator[](const char* key) const {
  if (!value_->is_object()) fail("expected an object, got " + type_name(*value_));
  const auto it = value_->find(key);
  if (it == value_->end()) JsonField(*value_, file_, child_path(key)).fail("missing");
  return JsonField(*it, file_, child_path(key));
}

std::optional<JsonField> JsonField::optional(const char* key) const {
  if (!has(key)) return std::nullopt;
  return (*this)[key];
}

void JsonField::only_keys(std::initializer_list<const char*> allowed) const {
  if (!value_->is_object()) fail("expected an object, got " + type_name(*value_));
  for (const auto& item : value_->items()) {
    const bool known = std::any_of(allowed.begin(), allowed.end(),
                                   [&](const char* k) { return item.key() == k; });
    if (!known) {
      std::string list;
      for (const char* k : allowed) list += std::string(list.empty() ? "" : ", ") + k;
      JsonField(item.value(), file_, child_path(item.key())).fail("unknown key (known here: " + list + ")");
    }
  }
}

std::vector<JsonField> JsonField::items(std::size_t min_count) const {
  if (!value_->is_array()) fail("expected an array, got " + type_name(*value_));
  if (value_->size() < min_count) fail("expected at least " + std::to_string(min_count) + " entries");
  std::vector<JsonField> out;
  for (std::size_t i = 0; i < value_->size(); ++i) {
    out.emplace_back((*value_)[i], file_, path_ + "[" + std::to_string(i) + "]");
  }
  return out;
}

std::string JsonField::string() const {
  if (!value_->is_string()) fail("expected a string, got " + type_name(*value_));
  return value_->get<std::string>();
}

bool JsonField::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false, got " + type_name(*value_));
  return value_->get<bool>();
}

double JsonField::number(double min, double max) const {
  if (!value_->is_number()) fail("expected a number, got " + type_name(*value_));
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("number is not finite");
  if (v < min || v > max) {
    fail("must be between " + format_number(min) + " and " + format_number(max) + ", got " + format_number(v));
  }
  return v;
}

int JsonField::integer(int min, int max) const {
  const double v = number(min, max);
  if (v != std::floor(v)) fail("expected a whole number");
  return static_cast<int>(v);
}

std::vector<double> JsonField::numbers(std::size_t count, double min, double max) const {
  if (!value_->is_array() || value_->size() != count) {
    fail("expected an array of " + std::to_string(count) + " numbers, got " +
         (value_->is_array() ? std::to_string(value_->size()) + " entries" : type_name(*value_)));
  }
  std::vector<double> out;
  for (const JsonField& item : items()) out.push_back(item.number(min, max));
  return out;
}

glm::vec2 JsonField::range(double min, double max) const {
  const std::vector<double> ends = numbers(2, min, max);
  if (ends[0] > ends[1]) fail("the smaller number comes first");
  return {ends[0], ends[1]};
}

glm::vec3 JsonField::vec3(double limit) const {
  const std::vector<double> v = numbers(3, -limit, limit);
  return {v[0], v[1], v[2]};
}

glm::vec3 JsonField::color() const {
  const std::vector<double> v = numbers(3, 0.0, 1.0);
  return {v[0], v[1], v[2]};
}

}  // namespace ecoview
