// The README and docs/*.md held to the rules that keep them readable: a short front page, no line
// or table cell too long to read at once, links that lead somewhere, nothing outside the repository.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace ecoview {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t max_line_characters = 200;
constexpr std::size_t max_table_row_characters = 300;

struct Line {
  int number = 0;  // from 1
  std::string text;
  bool in_code = false;  // inside a fenced code block, or a fence itself
};

struct Document {
  fs::path path;
  std::string name;  // relative to the repository, for messages
  std::vector<Line> lines;
};

Document read_document(const fs::path& path) {
  Document doc{path, fs::relative(path, test::source_dir()).string(), {}};
  std::istringstream in(test::read_bytes(path));
  bool fenced = false;
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const std::size_t start = text.find_first_not_of(" \t");
    const bool fence = start != std::string::npos && (text.compare(start, 3, "```") == 0 || text.compare(start, 3, "~~~") == 0);
    doc.lines.push_back({number, text, fenced || fence});
    if (fence) fenced = !fenced;
  }
  return doc;
}

// README.md and every docs/*.md, as they are in the source folder.
std::vector<Document> documents() {
  std::vector<Document> docs{read_document(test::source_dir() / "README.md")};
  std::vector<fs::path> pages;
  for (const fs::directory_entry& entry : fs::directory_iterator(test::source_dir() / "docs")) {
    if (entry.is_regular_file() && entry.path().extension() == ".md") pages.push_back(entry.path());
  }
  std::sort(pages.begin(), pages.end());
  for (const fs::path& page : pages) docs.push_back(read_document(page));
  return docs;
}

// Characters, not bytes: UTF-8 continuation bytes do not count.
std::size_t characters(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

bool is_table_row(const std::string& text) {
  const std::size_t start = text.find_first_not_of(" \t");
  return start != std::string::npos && text[start] == '|';
}

// A table row's cells, split at the bars that are not escaped (`\|`).
std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
      cell += "\\|";
      ++i;
    } else if (row[i] == '|') {
      out.push_back(cell);
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  out.push_back(cell);
  for (std::string& c : out) {
    const std::size_t first = c.find_first_not_of(" \t");
    const std::size_t last = c.find_last_not_of(" \t");
    c = first == std::string::npos ? "" : c.substr(first, last - first + 1);
  }
  return out;
}

std::string where(const Document& doc, const Line& line) { return doc.name + ":" + std::to_string(line.number); }

TEST(Documents, TheReadmeIsAtMost200Lines) {
  const Document readme = read_document(test::source_dir() / "README.md");
  EXPECT_LE(readme.lines.size(), 200u) << "README.md has " << readme.lines.size()
                                       << " lines; move details into a page under docs/";
}

TEST(Documents, TheReadmeStartsWithTheTwoSetUpCommands) {
  const Document readme = read_document(test::source_dir() / "README.md");
  std::vector<std::string> commands;  // the first line of each fenced block, in order
  bool inside = false;
  for (std::size_t i = 0; i < readme.lines.size() && commands.size() < 2; ++i) {
    if (readme.lines[i].text.rfind("```", 0) != 0) continue;
    if (!inside && i + 1 < readme.lines.size()) commands.push_back(readme.lines[i + 1].text);
    inside = !inside;
  }
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0], "./scripts/setup.sh && ./build/ecoview capture --path ecosystem --fps 5 --size 960x540 "
                         "--aov color,shadow --out capture");
  EXPECT_EQ(commands[1], "./scripts/setup.sh tests && ctest --test-dir build --output-on-failure");
}

TEST(Documents, NoLineOfProseIsOver200Characters) {
  std::string long_lines;
  for (const Document& doc : documents()) {
    for (const Line& line : doc.lines) {
      if (line.in_code || is_table_row(line.text)) continue;
      if (characters(line.text) > max_line_characters) {
        long_lines += "\n  " + where(doc, line) + ": " + std::to_string(characters(line.text)) + " characters";
      }
    }
  }
  EXPECT_TRUE(long_lines.empty()) << "lines over " << max_line_characters << " characters (wrap them at about 100):"
                                  << long_lines;
}

TEST(Documents, NoTableCellIsOver200CharactersNorARowOver300) {
  std::string long_cells;
  for (const Document& doc : documents()) {
    for (const Line& line : doc.lines) {
      if (line.in_code || !is_table_row(line.text)) continue;
      for (const std::string& cell : cells(line.text)) {
        if (characters(cell) > max_line_characters) {
          long_cells += "\n  " + where(doc, line) + ": a cell of " + std::to_string(characters(cell)) + " characters";
        }
      }
      // A row of short cells can still be too much to read across: a table of long cells is a list.
      if (characters(line.text) > max_table_row_characters) {
        long_cells += "\n  " + where(doc, line) + ": a row of " + std::to_string(characters(line.text)) + " characters";
      }
    }
  }
  EXPECT_TRUE(long_cells.empty()) << "table cells over " << max_line_characters
                                  << " characters, or rows over " << max_table_row_characters << " (move the detail into prose below the table):" << long_cells;
}

TEST(Documents, EveryRelativeLinkAndImageNamesAFileThatExists) {
  // [text](target) and ![alt](target), the target up to a space, '#' or ')'.
  const std::regex link(R"(\]\(([^)#\s]*)(#[^)\s]*)?(\s+"[^"]*")?\))");
  const std::regex scheme(R"(^[A-Za-z][A-Za-z0-9+.-]*:)");
  std::string broken;
  int checked = 0;
  for (const Document& doc : documents()) {
    for (const Line& line : doc.lines) {
      if (line.in_code) continue;
      for (auto m = std::sregex_iterator(line.text.begin(), line.text.end(), link); m != std::sregex_iterator(); ++m) {
        const std::string target = (*m)[1].str();
        if (target.empty() || std::regex_search(target, scheme)) continue;  // an anchor in the page, or a URL
        ++checked;
        if (!fs::exists(doc.path.parent_path() / target)) broken += "\n  " + where(doc, line) + ": " + target;
      }
    }
  }
  EXPECT_GT(checked, 0);
  EXPECT_TRUE(broken.empty()) << "links to files that do not exist:" << broken;
}

TEST(Documents, NoDocumentPointsOutsideTheRepository) {
  std::string mentions;
  for (const Document& doc : documents()) {
    for (const Line& line : doc.lines) {
      for (const char* outside : {"DESIGN.md", "../shared"}) {
        if (line.text.find(outside) != std::string::npos) mentions += "\n  " + where(doc, line) + ": " + outside;
      }
    }
  }
  EXPECT_TRUE(mentions.empty()) << "documents name files outside the repository:" << mentions;
}

// The code's comments send a reader to docs/, never to a design file the repository lacks. (The
// optional glTF test files beside a checkout are named by the tests that use them.)
TEST(Documents, NoSourceFilePointsOutsideTheRepository) {
  std::string mentions;
  int read = 0;
  for (const char* folder : {"app", "pointgen", "shadow", "shaders", "scripts", "tests"}) {
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(test::source_dir() / folder)) {
      if (!entry.is_regular_file() || entry.path().filename() == "documents_test.cpp") continue;  // this file names them
      ++read;
      const Document doc = read_document(entry.path());
      for (const Line& line : doc.lines) {
        if (line.text.find("DESIGN.md") != std::string::npos) mentions += "\n  " + where(doc, line);
      }
    }
  }
  EXPECT_GT(read, 100);
  EXPECT_TRUE(mentions.empty()) << "source files name files outside the repository:" << mentions;
}

}  // namespace
}  // namespace ecoview
