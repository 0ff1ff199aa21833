#include "pointgen/declared_counts.hpp"

#include "pointgen/file_error.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>
#include <sstream>
#include <vector>

namespace pointgen {
namespace {

// Largest polygon accepted, in vertices.
constexpr double max_face_size = 65535;

// Whitespace-separated tokens, skipping '#' comments (OFF allows them anywhere).
class Tokens {
 public:
  explicit Tokens(std::istream& in) : in_(in) {}
  bool next(std::string& token) {
    while (in_ >> token) {
      if (token[0] != '#') return true;
      std::string rest;
      std::getline(in_, rest);
    }
    return false;
  }
  bool number(double& value) {
    std::string token;
    if (!next(token)) return false;
    std::istringstream s(token);
    return static_cast<bool>(s >> value);
  }

 private:
  std::istream& in_;
};

void check_off(const std::string& path, const std::string& bytes) {
  std::istringstream in(bytes);
  Tokens tokens(in);
  std::string keyword;
  if (!tokens.next(keyword)) throw FileError(path, "is empty");
  if (keyword.find("OFF") == std::string::npos) throw FileError(path, "does not start with an OFF keyword");
  std::string line;
  std::getline(in, line);
  if (line.find("BINARY") != std::string::npos) throw FileError(path, "binary OFF is not supported; use ASCII OFF or PLY");
  double vertices = 0, faces = 0, edges = 0;
  if (!tokens.number(vertices) || !tokens.number(faces) || !tokens.number(edges)) {
    throw FileError(path, "has no vertex, face and edge counts after its keyword");
  }
  if (vertices < 0 || faces < 0 || vertices > static_cast<double>(bytes.size()) || faces > static_cast<double>(bytes.size())) {
    throw FileError(path, "declares more vertices or faces than its size allows (corrupt file?)");
  }
  std::getline(in, line);
  for (double v = 0; v < vertices && std::getline(in, line);) {
    const std::size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    if (!three_finite_numbers(line.c_str() + start)) {
      throw FileError(path, "vertex " + std::to_string(static_cast<long long>(v)) + " is not three finite numbers");
    }
    ++v;
  }
  for (double f = 0; f < faces; ++f) {
    double size = 0;
    if (!tokens.number(size)) return;  // a short file is OpenMesh's to report
    if (size < 0 || size > std::min(vertices, max_face_size)) {
      throw FileError(path, "face " + std::to_string(static_cast<long long>(f)) + " declares " +
                                std::to_string(static_cast<long long>(size)) + " vertices (corrupt file?)");
    }
    std::getline(in, line);
  }
}

struct PlyProperty {
  bool list = false;
  std::string count_type;
};
struct PlyElement {
  std::string name;
  double count = 0;
  std::vector<PlyProperty> properties;
};

bool is_ply_type(const std::string& type) {
  static const std::set<std::string> types = {"char",  "uchar",  "short",  "ushort",  "int",     "uint",    "float",
                                              "double", "int8", "uint8", "int16", "uint16", "int32", "uint32",
                                              "float32", "float64"};
  return types.count(type) > 0;
}

// `property TYPE NAME` or `property list COUNT_TYPE ITEM_TYPE NAME`. OpenMesh spins forever on a
// property without a name, and prints its own message for an unknown type.
PlyProperty ply_property(const std::string& path, const std::string& line) {
  std::istringstream fields(line);
  std::string keyword, type, count_type, name, extra;
  fields >> keyword >> type;
  PlyProperty p;
  p.list = type == "list";
  if (p.list) fields >> count_type >> type;
  fields >> name;
  const bool well_formed = !name.empty() && !(fields >> extra) && is_ply_type(type) && (!p.list || is_ply_type(count_type));
  if (!well_formed) {
    throw FileError(path, "PLY property line '" + line.substr(0, 40) + "' is not 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME' with PLY types");
  }
  p.count_type = count_type;
  return p;
}

void check_ply(const std::string& path, const std::string& bytes) {
  std::istringstream in(bytes);
  std::string line, format;
  std::vector<PlyElement> elements;
  bool header_ended = false;
  while (!header_ended && std::getline(in, line)) {
    std::istringstream fields(line);
    std::string keyword;
    fields >> keyword;
    // OpenMesh loops forever on some malformed headers (one without end_header, for one): only
    // well-formed ones reach it.
    if (keyword == "end_header") {
      header_ended = true;
    } else if (keyword != "ply" && keyword != "format" && keyword != "element" && keyword != "property" &&
               keyword != "comment" && keyword != "obj_info") {
      throw FileError(path, "unknown PLY header line '" + line.substr(0, 40) + "'");
    } else if (keyword == "format") {
      fields >> format;
    } else if (keyword == "element") {
      PlyElement e;
      fields >> e.name >> e.count;
      if (!fields || e.count < 0 || e.count > static_cast<double>(bytes.size())) {
        throw FileError(path, "element '" + e.name + "' declares more entries than the file's size allows (corrupt file?)");
      }
      elements.push_back(e);
    } else if (keyword == "property") {
      if (elements.empty()) throw FileError(path, "PLY property line before any element: '" + line.substr(0, 40) + "'");
      elements.back().properties.push_back(ply_property(path, line));
    }
  }
  if (!header_ended) throw FileError(path, "has no end_header line");
  if (format != "ascii") {
    // Binary list counts are read as stored: allow only 8- and 16-bit ones.
    for (const PlyElement& e : elements) {
      for (const PlyProperty& p : e.properties) {
        if (p.list && p.count_type != "uchar" && p.count_type != "uint8" && p.count_type != "char" &&
            p.count_type != "int8" && p.count_type != "ushort" && p.count_type != "uint16") {
          throw FileError(path, "binary list counts of type '" + p.count_type + "' are not supported (use uchar or ushort)");
        }
      }
    }
    return;
  }
  Tokens tokens(in);
  for (const PlyElement& e : elements) {
    for (double i = 0; i < e.count; ++i) {
      for (const PlyProperty& p : e.properties) {
        double value = 0;
        if (!tokens.number(value)) return;  // a short file is OpenMesh's to report
        if (!p.list) continue;
        if (value < 0 || value > max_face_size) {
          throw FileError(path, "a list in element '" + e.name + "' declares " + std::to_string(static_cast<long long>(value)) +
                                    " entries (corrupt file?)");
        }
        double entry = 0;
        for (double k = 0; k < value; ++k) tokens.number(entry);
      }
    }
  }
}

}  // namespace

bool three_finite_numbers(const char* text) {
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text || !(std::abs(value) <= std::numeric_limits<float>::max())) return false;
    text = end;
  }
  return true;
}

void check_declared_counts(const std::string& path, const std::string& ext, const std::string& bytes) {
  if (ext == ".off") check_off(path, bytes);
  if (ext == ".ply") check_ply(path, bytes);
}

}  // namespace pointgen
