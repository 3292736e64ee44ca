// Input limits of the `tolip` program (issue 10, part 4; docs/cli.md "Input limits"): endless and
// oversized input files are read only up to their cap (read_file_capped), with a message naming
// the file and the cap, exit 2; a directory given as an input is named a directory. Every command
// runs under a memory and a time limit (run_tolip_bounded).
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "tolip_ground/capped_read.hpp"

namespace tolip::test {
namespace {

namespace fs = std::filesystem;

// A sparse file of `size` bytes (no disk space used).
std::string sparse_file(const ScratchDirectory& scratch, const std::string& name, off_t size) {
  const std::string path = (scratch / name).string();
  std::ofstream(path).close();
  EXPECT_EQ(::truncate(path.c_str(), size), 0) << path;
  return path;
}

TEST(InputLimits, InspectOfAnEndlessDeviceStopsAtTheImageSizeAndExitsTwo) {
  const CommandResult result = run_tolip_bounded({"inspect", "/dev/zero"});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;
  EXPECT_EQ(result.err,
            "tolip: /dev/zero: more than 1580 bytes: a guidance table image is at most 1580 bytes "
            "(docs/cli.md, \"Input limits\")\n");
}

TEST(InputLimits, EndlessDeckIsCutAtTheDeckCapForEveryDeckCommand) {
  ScratchDirectory scratch("hostile_endless_deck");
  const std::string cap = std::to_string(tolip::ground::kMaxDeckFileBytes);
  const std::vector<std::vector<std::string>> commands = {
      {"simulate", "/dev/zero"},
      {"optimize", "/dev/zero"},
      {"export", "/dev/zero", "--out", (scratch / "t.bin").string()},
      {"convert", "/dev/zero", "--to", (scratch / "d.toml").string()},
  };
  for (const std::vector<std::string>& command : commands) {
    const CommandResult result = run_tolip_bounded(command);
    EXPECT_EQ(result.exit_code, 2) << command[0] << ": " << result.err;
    EXPECT_EQ(result.err, "tolip: /dev/zero: more than " + cap + " bytes: a deck file is at most " + cap +
                              " bytes (docs/cli.md, \"Input limits\")\n")
        << command[0];
  }
  EXPECT_TRUE(scratch.entries().empty());
}

TEST(InputLimits, OversizedDeckFilesOfBothFormatsAreRefusedBeforeReading) {
  ScratchDirectory scratch("hostile_big_deck");
  const std::string cap = std::to_string(tolip::ground::kMaxDeckFileBytes);
  // A TOML deck and a card deck, each a byte past the cap (sparse: NUL bytes beyond the text).
  for (const std::string& name : {std::string("big.toml"), std::string("big.dat")}) {
    const std::string path = (scratch / name).string();
    fs::copy_file(scout_example(name == "big.toml" ? "mission.toml" : "mission.dat"), path);
    ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(tolip::ground::kMaxDeckFileBytes + 1)), 0);
    const CommandResult result = run_tolip_bounded({"simulate", path});
    EXPECT_EQ(result.exit_code, 2) << name;
    EXPECT_EQ(result.err, "tolip: " + path + ": more than " + cap + " bytes: a deck file is at most " + cap +
                              " bytes (docs/cli.md, \"Input limits\")\n");
  }
}

TEST(InputLimits, EndlessAndOversizedResultFilesAreRefusedByPlot) {
  ScratchDirectory scratch("hostile_big_result");
  const std::string cap = std::to_string(tolip::ground::kMaxResultFileBytes);
  const std::string big =
      sparse_file(scratch, "big.json", static_cast<off_t>(tolip::ground::kMaxResultFileBytes + 1));
  for (const std::string& source : {std::string("/dev/zero"), big}) {
    const CommandResult result = run_tolip_bounded({"plot", source, "--out", (scratch / "plots").string()});
    EXPECT_EQ(result.exit_code, 2) << source << ": " << result.err;
    EXPECT_EQ(result.err, "tolip: " + source + ": more than " + cap + " bytes: a result file is at most " +
                              cap + " bytes (docs/cli.md, \"Input limits\")\n");
  }
  EXPECT_FALSE(fs::exists(scratch / "plots"));
}

TEST(CappedRead, ReadsUpToTheCapAndRefusesOneBytePast) {
  ScratchDirectory scratch("capped_read");
  const std::string path = (scratch / "ten.txt").string();
  std::ofstream(path) << "0123456789";
  std::string contents;
  std::string error;
  EXPECT_TRUE(tolip::ground::read_file_capped(path, 10, "test file", &contents, &error)) << error;
  EXPECT_EQ(contents, "0123456789");
  contents = "unchanged";
  EXPECT_FALSE(tolip::ground::read_file_capped(path, 9, "test file", &contents, &error));
  EXPECT_EQ(error, "more than 9 bytes: a test file is at most 9 bytes (docs/cli.md, \"Input limits\")");
  EXPECT_EQ(contents, "unchanged");
  // A stream without a size (a character device) is cut at the cap too.
  EXPECT_FALSE(tolip::ground::read_file_capped("/dev/zero", 1000, "test file", &contents, &error));
  EXPECT_TRUE(contains(error, "more than 1000 bytes")) << error;
  EXPECT_TRUE(tolip::ground::read_file_capped("/dev/null", 0, "test file", &contents, &error)) << error;
  EXPECT_EQ(contents, "");
  EXPECT_FALSE(tolip::ground::read_file_capped(scratch.path().string(), 10, "test file", &contents, &error));
  EXPECT_EQ(error, "is a directory, not a test file");
  EXPECT_FALSE(
      tolip::ground::read_file_capped((scratch / "absent").string(), 10, "test file", &contents, &error));
  EXPECT_EQ(error, "cannot open the test file: No such file or directory");
}

// A directory where a file belongs is named a directory (not "missing required table [case]", not
// "basic_filebuf::underflow").
TEST(InputLimits, DirectoryGivenAsAnInputIsNamedADirectory) {
  ScratchDirectory scratch("hostile_directory_input");
  const std::string dir = scratch.path().string();
  const struct {
    std::vector<std::string> command;
    std::string message;
  } cases[] = {
      {{"simulate", dir}, "tolip: " + dir + ": is a directory, not a deck file\n"},
      {{"convert", dir, "--to", (scratch / "x.toml").string()},
       "tolip: " + dir + ": is a directory, not a deck file\n"},
      {{"inspect", dir}, "tolip: " + dir + ": is a directory, not a guidance table image\n"},
      {{"plot", dir, "--out", (scratch / "plots").string()},
       "tolip: " + dir + ": is a directory, not a result file\n"},
  };
  for (const auto& c : cases) {
    const CommandResult result = run_tolip_bounded(c.command);
    EXPECT_EQ(result.exit_code, 2) << c.command[0];
    EXPECT_EQ(result.err, c.message) << c.command[0];
  }
}

}  // namespace
}  // namespace tolip::test
