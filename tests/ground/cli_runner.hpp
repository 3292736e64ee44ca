// Runs the built `tolip` program (repository_paths::tolip_executable()) in a shell and captures its exit
// code, stdout and stderr, for the command-line tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "support/reference_data.hpp"
#include "support/repository_paths.hpp"
#include "support/text_match.hpp"

namespace tolip::test {

struct CommandResult {
  int exit_code = -1;  // -1 when the program did not exit normally
  std::string out;
  std::string err;
};

// Single-quotes an argument for /bin/sh.
inline std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

inline std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A fresh, empty scratch directory for one test; removed by the destructor.
class ScratchDirectory {
 public:
  explicit ScratchDirectory(const std::string& name) {
    path_ = std::filesystem::temp_directory_path() /
            ("tolip_test_" + name + "_" + std::to_string(static_cast<long long>(::getpid())));
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  // Names of the entries in the directory (to spot left-over temporary files).
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

  // Whether an atomic write left its temporary file (FILE.tmp.<pid>) behind.
  bool has_temp_file() const {
    for (const std::string& name : entries()) {
      if (name.find(".tmp.") != std::string::npos) return true;
    }
    return false;
  }

 private:
  std::filesystem::path path_;
};

// Runs a shell command line whose stderr goes to `err_path`: stdout, stderr and the exit code.
inline CommandResult run_capturing(const std::string& command, const std::filesystem::path& err_path) {
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[65536];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, got);
  const int status = ::pclose(pipe);
  if (status != -1 && WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.err = read_text_file(err_path);
  std::error_code ignored;
  std::filesystem::remove(err_path, ignored);
  return result;
}

// A scratch file for one run's stderr, unique in this process.
inline std::filesystem::path stderr_path(const char* prefix) {
  static int counter = 0;
  return std::filesystem::temp_directory_path() /
         (std::string(prefix) + std::to_string(static_cast<long long>(::getpid())) + "_" +
          std::to_string(++counter));
}

// Runs the tolip program with the arguments; stderr is captured through a scratch file.
inline CommandResult run_tolip_executable(std::initializer_list<std::string> arguments) {
  const std::filesystem::path err_path = stderr_path("tolip_test_stderr_");
  std::string command = shell_quote(tolip::repository_paths::tolip_executable());
  for (const std::string& argument : arguments) command += " " + shell_quote(argument);
  command += " 2>" + shell_quote(err_path.string());
  return run_capturing(command, err_path);
}

// The memory bound of run_tolip_bounded. AddressSanitizer reserves terabytes of shadow address
// space at start-up, so under it (the asan preset) an address-space limit stops every run; there
// the same 1 GiB bounds the resident size through ASan's own hard_rss_limit_mb instead.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr const char* kBoundedMemoryPrefix =
    "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}hard_rss_limit_mb=1024\"; export ASAN_OPTIONS; ";
#else
inline constexpr const char* kBoundedMemoryPrefix = "ulimit -v 1048576; ";
#endif

// Runs the tolip program like run_tolip_executable, but with at most 1 GiB of memory and 60 s: for
// hostile inputs, so that a regression (an endless read) fails the test instead of taking the
// machine down.
inline CommandResult run_tolip_bounded(const std::vector<std::string>& arguments) {
  const std::filesystem::path err_path = stderr_path("tolip_hostile_stderr_");
  std::string command = std::string(kBoundedMemoryPrefix) + "exec timeout -s KILL 60 " +
                        shell_quote(tolip::repository_paths::tolip_executable());
  for (const std::string& argument : arguments) command += " " + shell_quote(argument);
  command += " 2>" + shell_quote(err_path.string());
  return run_capturing("sh -c " + shell_quote(command), err_path);
}

// stderr without the "tolip: warning: " lines of inputs read but not acted on (the bundled example
// asks for analyses this version does not compute; tolip_ground/unused_inputs.hpp).
inline std::string without_input_warnings(const std::string& err) {
  std::string kept;
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("tolip: warning: ", 0) != 0) kept += line + "\n";
  }
  if (!err.empty() && err.back() != '\n' && !kept.empty()) kept.pop_back();
  return kept;
}

// The bundled example deck examples/scout/mission.toml with each `from` replaced by its `to` (each
// must occur; a missing one fails the calling test), written as `name` into the scratch folder.
inline std::string edited_example_deck(const ScratchDirectory& scratch, const std::string& name,
                                       const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text =
      read_text_file(std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.toml");
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos) return {};
    text.replace(at, from.size(), to);
  }
  const std::string path = (scratch / name).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace tolip::test
