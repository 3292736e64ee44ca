// docs/user-guide.md works from a clone: every `tolip` command of its shell blocks, and every
// complete `tolip ...` command quoted in its text, runs in document order and exits 0, from a
// folder holding only the repository's examples/ (what a clone has) and the files the guide's
// earlier commands wrote.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.hpp"
#include "support/repository_paths.hpp"

namespace tolip::test {
namespace {

namespace fs = std::filesystem;

std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  const std::size_t last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

// The guide's commands in document order: the lines of ```sh blocks (comments and a final
// "| less" removed; the setup scripts and the PATH export left out, the test provides both) and
// the inline `tolip ...` commands of three words or more without a placeholder (COMMAND, DECK).
std::vector<std::string> guide_commands(const std::string& guide) {
  std::vector<std::pair<std::size_t, std::string>> found;
  const std::regex block(R"(```sh\n([\s\S]*?)```)");
  for (std::sregex_iterator it(guide.begin(), guide.end(), block), end; it != end; ++it) {
    std::istringstream lines((*it)[1].str());
    std::string line;
    while (std::getline(lines, line)) {
      const std::size_t hash = line.find(" #");
      if (hash != std::string::npos) line = line.substr(0, hash);
      line = trim(line);
      const std::size_t pager = line.rfind("| less");
      if (pager != std::string::npos && pager + 6 == line.size()) line = trim(line.substr(0, pager));
      if (line.empty() || line.rfind("scripts/", 0) == 0 || line.rfind("export PATH", 0) == 0) continue;
      found.emplace_back(static_cast<std::size_t>(it->position(0)), line);
    }
  }
  const std::regex inline_command(R"(`(tolip [^`]+)`)");
  const std::regex placeholder(R"(\b[A-Z]{3,}\b)");
  for (std::sregex_iterator it(guide.begin(), guide.end(), inline_command), end; it != end; ++it) {
    std::string command = (*it)[1].str();
    for (char& c : command) {
      if (c == '\n') c = ' ';
    }
    std::istringstream words(command);
    int count = 0;
    for (std::string word; words >> word;) ++count;
    if (count < 3 || std::regex_search(command, placeholder)) continue;
    found.emplace_back(static_cast<std::size_t>(it->position(0)), command);
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> commands;
  for (const auto& entry : found) commands.push_back(entry.second);
  return commands;
}

TEST(UserGuide, EveryCommandRunsFromAClone) {
  const std::string guide =
      read_text_file(std::string(tolip::repository_paths::source_dir()) + "/docs/user-guide.md");
  const std::vector<std::string> commands = guide_commands(guide);
  ASSERT_GE(commands.size(), 15u) << "the guide's commands were not found";
  const bool gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;

  ScratchDirectory scratch("user_guide");
  fs::create_directory_symlink(tolip::repository_paths::examples_dir(), scratch / "examples");
  const std::string path = fs::path(tolip::repository_paths::tolip_executable()).parent_path().string();
  for (const std::string& command : commands) {
    if (!gnuplot && command.find("plot") != std::string::npos) continue;
    const std::string shell = "cd " + shell_quote(scratch.path().string()) + " && PATH=" + shell_quote(path) +
                              ":\"$PATH\" && { " + command + "; } > /dev/null 2> guide_stderr.txt";
    const int status = std::system(shell.c_str());
    EXPECT_EQ(status, 0) << "docs/user-guide.md: '" << command << "' failed:\n"
                         << read_text_file(scratch / "guide_stderr.txt");
  }
}

}  // namespace
}  // namespace tolip::test
