#include "pointgen/obj_references.hpp"

#include "pointgen/declared_counts.hpp"
#include "pointgen/file_error.hpp"

#include <array>
#include <cctype>
#include <filesystem>
#include <set>
#include <sstream>

namespace pointgen {
namespace {

constexpr const char* kinds[3] = {"vertex", "texture coordinate", "normal"};

// 0 for "v", 1 for "vt", 2 for "vn", -1 for anything else.
int kind_of(const std::string& keyword) {
  if (keyword == "v") return 0;
  if (keyword == "vt") return 1;
  if (keyword == "vn") return 2;
  return -1;
}

// Checks one face corner ("v", "v/vt", "v//vn" or "v/vt/vn") against the file's counts and those
// before the face.
void check_corner(const std::string& path, long long line, const std::string& corner, const std::array<long long, 3>& total,
                  const std::array<long long, 3>& before) {
  std::istringstream parts(corner);
  std::string part;
  for (int k = 0; k < 3 && std::getline(parts, part, '/'); ++k) {
    if (part.empty() && k > 0) continue;
    long long index = 0;
    try {
      index = std::stoll(part);
    } catch (const std::exception&) {
      index = 0;
    }
    if (index == 0 || index > total[k] || index < -before[k]) {
      throw FileError(path, "line " + std::to_string(line) + ": a face refers to " + kinds[k] + " '" + part.substr(0, 20) +
                                "', of " + std::to_string(total[k]) + " in the file (corrupt file?)");
    }
  }
}

// Calls visit(line number, line, its first word, a stream of the words after it) for each line.
template <class Visit>
void for_each_line(const std::string& bytes, Visit visit) {
  std::istringstream in(bytes);
  long long number = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string keyword;
    fields >> keyword;
    visit(++number, line, keyword, fields);
  }
}

}  // namespace

void check_obj_references(const std::string& path, const std::string& bytes) {
  std::array<long long, 3> total = {0, 0, 0};
  for_each_line(bytes, [&](long long number, const std::string& line, const std::string& keyword, std::istringstream&) {
    const int kind = kind_of(keyword);
    if (kind == 0 && !three_finite_numbers(line.c_str() + line.find('v') + 1)) {
      throw FileError(path, "line " + std::to_string(number) + ": a vertex that is not three finite numbers");
    }
    if (kind >= 0) ++total[static_cast<std::size_t>(kind)];
  });
  std::array<long long, 3> before = {0, 0, 0};
  for_each_line(bytes, [&](long long number, const std::string&, const std::string& keyword, std::istringstream& fields) {
    if (const int kind = kind_of(keyword); kind >= 0) ++before[static_cast<std::size_t>(kind)];
    if (keyword != "f") return;
    for (std::string corner; fields >> corner && corner[0] != '#';) check_corner(path, number, corner, total, before);
  });
}

void check_material_libraries(const std::string& path, const std::string& bytes, const ReadFile& read, const Note& note) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  // Each library is checked once: a short OBJ naming one large file again and again must not
  // read it again and again.
  std::set<std::string> checked;
  for_each_line(bytes, [&](long long number, const std::string&, const std::string& keyword, std::istringstream& fields) {
    if (keyword != "mtllib") return;
    for (std::string library; fields >> library && library[0] != '#';) {
      if (!checked.insert(library).second) continue;
      try {
        read((folder / library).string());
      } catch (const FileError& refused) {
        throw FileError(path, "line " + std::to_string(number) + ": mtllib: " + refused.what());
      }
    }
  });
  if (!checked.empty() && note) note(path + ": ignored: material libraries (OBJ materials are not used; vertex colours are)");
}

std::string without_material_libraries(std::string bytes) {
  const std::string keyword = "mtllib";
  for (std::size_t line = 0; line < bytes.size();) {
    const std::size_t word = bytes.find_first_not_of(" \t\r\v\f", line);
    const std::size_t after = word == std::string::npos ? word : word + keyword.size();
    if (word != std::string::npos && bytes.compare(word, keyword.size(), keyword) == 0 &&
        (after >= bytes.size() || std::isspace(static_cast<unsigned char>(bytes[after])))) {
      bytes[word] = '#';
    }
    line = bytes.find('\n', line);
    if (line != std::string::npos) ++line;
  }
  return bytes;
}

}  // namespace pointgen
