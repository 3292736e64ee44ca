// Regressions found by the libFuzzer targets (fuzz/, docs/verification/fuzzing.md), in the
// Release suite: each input that crashed a reader, and the named rejection it must get instead.
// Verifies: REQ-DCK-005, REQ-GND-002
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "support/text_match.hpp"

namespace tolip::test {
namespace {

// fuzz/regressions/plot_result/number_overflow_out_of_range_406.json: a result whose number
// overflows a double made nlohmann throw out_of_range (not parse_error), which `tolip plot` did
// not catch: the program ended in std::terminate. Now: exit 2, the file named, nothing written.
TEST(PlotFuzzRegression, ANumberBeyondDoubleIsNamedAsInvalidJsonNotACrash) {
  ScratchDirectory scratch("plot_fuzz_overflow");
  const std::filesystem::path out = scratch / "out";
  const std::string path = (scratch / "overflow.json").string();
  std::ofstream(path) << "{\"trajectory\": [{\"time_s\": 9985.5754E6033248}]}";
  CommandResult plot = run_tolip_executable({"plot", path, "--out", out.string()});
  EXPECT_EQ(plot.exit_code, 2);
  EXPECT_TRUE(
      contains(plot.err, "tolip: " + path + ": not valid JSON: number overflow parsing '9985.5754E6033248'"))
      << plot.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace tolip::test
