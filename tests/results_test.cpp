// results.csv is RFC 4180: read back by a parser written here, every record has the header's
// fields and every value comes back as results.json has it.
#include "app/bench/results.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

// RFC 4180 records: fields split at commas outside quotes, "" inside quotes a quote, CRLF ends a
// record.
std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> records(1, std::vector<std::string>(1));
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    std::string& field = records.back().back();
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      records.back().emplace_back();
    } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
      records.emplace_back(1);
      ++i;
    } else {
      field += c;
    }
  }
  if (records.back() == std::vector<std::string>(1)) records.pop_back();  // after the last CRLF
  return records;
}

TEST(Results, CsvQuotesCommasQuotesAndLineBreaks) {
  const TempDir dir;
  BenchResults results;
  BenchRun a, b;
  a.params = {{"scene", "field"}, {"shadow_setup", "psm: directional light, camera moved back 0.0 m"}};
  a.figures = {{"err", 0.25}, {"frame_ms", 12}};
  b.params = {{"scene", "a \"quoted\" name"}, {"shadow_setup", "two\nlines\r\nhere"}};
  b.figures = {{"err", 0.5}};
  results.runs = {a, b};
  write_results(dir.path(), results);

  const auto records = parse_csv(read_bytes(dir / "results.csv"));
  ASSERT_EQ(records.size(), 3u);
  const std::vector<std::string> header = {"scene", "shadow_setup", "err", "frame_ms"};
  EXPECT_EQ(records[0], header);
  EXPECT_EQ(records[1], (std::vector<std::string>{"field", "psm: directional light, camera moved back 0.0 m", "0.25", "12"}));
  EXPECT_EQ(records[2], (std::vector<std::string>{"a \"quoted\" name", "two\nlines\r\nhere", "0.5", ""}));
}

// The machine block's CPU: x86 kernels name it "model name" once a core, ARM kernels
// "Hardware" or "Processor".
TEST(Results, CpuModelIsTheFirstModelNameInCpuinfo) {
  EXPECT_EQ(cpu_model("processor\t: 0\nvendor_id\t: AuthenticAMD\nmodel name\t: AMD EPYC 7B13 64-Core Processor\n\n"
                      "processor\t: 1\nmodel name\t: another\n"),
            "AMD EPYC 7B13 64-Core Processor");
  EXPECT_EQ(cpu_model("processor\t: 0\nBogoMIPS\t: 48.00\n\nHardware\t: BCM2835\n"), "BCM2835");
  EXPECT_EQ(cpu_model(""), "unknown");
}

// results.json says whether the run was quick, and reads back as written.
TEST(Results, JsonReadsBackWithItsQuickFlagMachineAndRuns) {
  const TempDir dir;
  BenchResults results;
  results.quick = true;
  results.machine = {{"cores", 2}};
  BenchRun run;
  run.params = {{"scene", "field"}};
  run.figures = {{"err", 0.25}};
  results.runs = {run};
  results.sections["extra"] = {{"note", 1}};
  write_results(dir.path(), results);
  const BenchResults read = read_results(dir / "results.json");
  EXPECT_TRUE(read.quick);
  EXPECT_EQ(read.machine, results.machine);
  ASSERT_EQ(read.runs.size(), 1u);
  EXPECT_EQ(read.runs[0].params, run.params);
  EXPECT_EQ(read.runs[0].figures, run.figures);
  EXPECT_EQ(nlohmann::json::parse(read_bytes(dir / "results.json"))["extra"]["note"], 1);
}

}  // namespace
}  // namespace ecoview::test
