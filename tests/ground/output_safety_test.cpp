// Outputs of the `tolip` program (issue 10, part 4; docs/cli.md "Outputs"): an output naming an
// input or another output of the command is refused before anything runs (exit 2), and only
// regular files are ever replaced: a FIFO, a symbolic link or a directory is left as it is.
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "tolip_ground/atomic_file.hpp"

namespace tolip::test {
namespace {

namespace fs = std::filesystem;

bool is_named_pipe(const fs::path& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0 && S_ISFIFO(info.st_mode);
}

TEST(Outputs, ExportRefusesAHeaderNamingTheImageFile) {
  ScratchDirectory scratch("hostile_export_same");
  const std::string image = (scratch / "t.bin").string();
  // The same file under two spellings.
  const std::string other_spelling = (scratch.path() / "." / "t.bin").string();
  const CommandResult result = run_tolip_bounded(
      {"export", scout_example("reference_optimum.toml"), "--out", image, "--c-header", other_spelling});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(result.err,
            "tolip: --out '" + image + "' and --c-header '" + other_spelling +
                "' name the same file: the header would replace the image; name two different files\n");
  EXPECT_TRUE(scratch.entries().empty());
}

TEST(Outputs, ExportRefusesAnOutputThatIsTheDeck) {
  ScratchDirectory scratch("hostile_export_deck");
  const std::string deck = (scratch / "deck.toml").string();
  fs::copy_file(scout_example("reference_optimum.toml"), deck);
  const std::string before = read_text_file(deck);
  const std::string link = (scratch / "link.toml").string();
  fs::create_symlink(deck, link);
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"export", deck, "--out", deck},
        std::vector<std::string>{"export", deck, "--out", (scratch / "t.bin").string(), "--c-header",
                                 link}}) {
    const CommandResult result = run_tolip_bounded(command);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_TRUE(contains(result.err, "is the input deck '" + deck + "'")) << result.err;
  }
  EXPECT_EQ(read_text_file(deck), before);
  EXPECT_FALSE(fs::exists(scratch / "t.bin"));
}

TEST(Outputs, ConvertRefusesToWriteOverItsInput) {
  ScratchDirectory scratch("hostile_convert_self");
  const std::string deck = (scratch / "a.toml").string();
  fs::copy_file(scout_example("mission.toml"), deck);
  const std::string before = read_text_file(deck);
  const std::string hard_link = (scratch / "b.toml").string();
  fs::create_hard_link(deck, hard_link);
  for (const std::string& target : {deck, (scratch.path() / "." / "a.toml").string(), hard_link}) {
    const CommandResult result = run_tolip_bounded({"convert", deck, "--to", target});
    EXPECT_EQ(result.exit_code, 2) << target << ": " << result.err;
    EXPECT_EQ(result.err, "tolip: --to '" + target + "' is the input deck '" + deck +
                              "': converting a deck onto itself would replace it; name another file\n");
  }
  EXPECT_EQ(read_text_file(deck), before);
}

TEST(Outputs, SimulateRefusesACsvFileThatIsTheDeck) {
  ScratchDirectory scratch("hostile_csv_deck");
  const std::string deck = (scratch / "deck.toml").string();
  fs::copy_file(scout_example("reference_optimum.toml"), deck);
  const std::string before = read_text_file(deck);
  const CommandResult result = run_tolip_bounded({"simulate", deck, "--csv", deck});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_TRUE(contains(result.err, "the --csv file '" + deck + "' is the input deck")) << result.err;
  EXPECT_EQ(read_text_file(deck), before);
}

TEST(Outputs, OutputsNeverReplaceAFifoASymlinkOrADirectory) {
  ScratchDirectory scratch("hostile_special_outputs");
  const fs::path fifo = scratch / "fifo.dat";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const fs::path target = scratch / "target.dat";
  std::ofstream(target) << "keep me\n";
  const fs::path link = scratch / "link.dat";
  fs::create_symlink(target, link);
  const fs::path directory = scratch / "directory.dat";
  fs::create_directory(directory);

  const struct {
    fs::path path;
    const char* kind;
  } outputs[] = {{fifo, "a FIFO (named pipe)"}, {link, "a symbolic link"}, {directory, "a directory"}};
  for (const auto& output : outputs) {
    const CommandResult result =
        run_tolip_bounded({"convert", scout_example("mission.toml"), "--to", output.path.string()});
    EXPECT_EQ(result.exit_code, 1) << output.kind;
    EXPECT_EQ(result.err,
              "tolip: refusing to replace '" + output.path.string() + "': it is " + output.kind +
                  "; tolip writes its outputs only as regular files (remove it or name another file)\n");
  }
  EXPECT_TRUE(is_named_pipe(fifo));
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_text_file(target), "keep me\n");
  EXPECT_TRUE(fs::is_directory(directory));
  const std::vector<std::string> entries = scratch.entries();
  const std::set<std::string> left(entries.begin(), entries.end());
  EXPECT_EQ(left, (std::set<std::string>{"fifo.dat", "target.dat", "link.dat", "directory.dat"}));
}

TEST(AtomicFile, RefusesToReplaceAnythingButARegularFile) {
  ScratchDirectory scratch("atomic_special");
  const fs::path fifo = scratch / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const fs::path link = scratch / "link";
  fs::create_symlink(scratch / "absent", link);  // dangling: rename would replace it too
  std::string error;
  EXPECT_FALSE(tolip::ground::write_file_atomically(fifo.string(), "x", &error));
  EXPECT_TRUE(contains(error, "it is a FIFO")) << error;
  EXPECT_TRUE(is_named_pipe(fifo));
  EXPECT_FALSE(tolip::ground::write_file_atomically(link.string(), "x", &error));
  EXPECT_TRUE(contains(error, "it is a symbolic link")) << error;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_FALSE(fs::exists(scratch / "absent"));
  EXPECT_EQ(scratch.entries().size(), 2u) << "no temporary file left";
}

TEST(AtomicFile, NamesSameFileSeesThroughSpellingsLinksAndHardLinks) {
  ScratchDirectory scratch("atomic_same_file");
  const fs::path a = scratch / "a.txt";
  std::ofstream(a) << "a";
  fs::create_symlink(a, scratch / "sym.txt");
  fs::create_hard_link(a, scratch / "hard.txt");
  using tolip::ground::names_same_file;
  EXPECT_TRUE(names_same_file(a.string(), (scratch.path() / "sub" / ".." / "a.txt").string()));
  EXPECT_TRUE(names_same_file(a.string(), (scratch / "sym.txt").string()));
  EXPECT_TRUE(names_same_file(a.string(), (scratch / "hard.txt").string()));
  EXPECT_TRUE(names_same_file((scratch / "new.txt").string(), (scratch.path() / "." / "new.txt").string()));
  EXPECT_FALSE(names_same_file(a.string(), (scratch / "new.txt").string()));
  EXPECT_FALSE(names_same_file(a.string(), ""));
}

}  // namespace
}  // namespace tolip::test
