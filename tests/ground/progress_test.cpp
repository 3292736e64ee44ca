// The terminal progress display (tolip_ground/progress.hpp): what it writes when forced on, that it
// writes nothing when off, and that `tolip optimize` stays silent on stderr when that is not a
// terminal (as under CTest).
#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "support/repository_paths.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/progress.hpp"

namespace tolip::test {
namespace {

using ground::OptimizerProgress;
using ground::ProgressLine;
using ground::ProgressMode;

// What is on screen after the carriage returns: the text after the last '\r' that is followed by
// something, with trailing blanks trimmed.
std::string visible(const std::string& written) {
  std::string line;
  std::size_t start = 0;
  while (start <= written.size()) {
    const std::size_t cr = written.find('\r', start);
    const std::string piece = written.substr(start, cr == std::string::npos ? std::string::npos : cr - start);
    // Overwriting: a later piece replaces the beginning of the line.
    if (piece.size() >= line.size()) {
      line = piece;
    } else {
      line.replace(0, piece.size(), piece);
    }
    if (cr == std::string::npos) break;
    start = cr + 1;
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

IterationRecord record(int run, double payoff, bool successful) {
  IterationRecord r;
  r.forward_run = run;
  r.payoff = payoff;
  r.successful = successful;
  return r;
}

TEST(Progress, ForcedOnWritesOneUpdatingLine) {
  std::ostringstream stream;
  ProgressLine line(stream, true, std::chrono::steady_clock::duration::zero());
  line.update("forward run 1  payoff 250.0 lb  unsuccessful");
  line.update("forward run 12  payoff 301.2 lb  successful");
  const std::string written = stream.str();
  EXPECT_EQ(written.find('\n'), std::string::npos) << "one line, rewritten in place";
  EXPECT_EQ(written.front(), '\r');
  EXPECT_EQ(visible(written), "forward run 12  payoff 301.2 lb  successful");

  // A shorter update leaves no tail of the longer one.
  line.update("short");
  EXPECT_EQ(visible(stream.str()), "short");

  // clear() blanks the line and returns to its start.
  line.clear();
  EXPECT_EQ(visible(stream.str()), "");
  EXPECT_EQ(stream.str().back(), '\r');
}

TEST(Progress, CountAndTotalForm) {
  std::ostringstream stream;
  ProgressLine line(stream, true, std::chrono::steady_clock::duration::zero());
  line.set_prefix("case 2/3");
  line.update("sample", 37, 500, "impact 412.0 n.mi.");
  EXPECT_EQ(visible(stream.str()), "case 2/3  sample 37/500 (7%)  impact 412.0 n.mi.");
  line.update("sample", 38, 0);
  EXPECT_EQ(visible(stream.str()), "case 2/3  sample 38");
}

TEST(Progress, LongLinesAreCutToTheTerminalWidth) {
  std::ostringstream stream;
  ProgressLine line(stream, true, std::chrono::steady_clock::duration::zero());
  line.update(std::string(200, 'x'));
  EXPECT_LE(visible(stream.str()).size(), 79u);
}

TEST(Progress, UpdatesCloserThanTheIntervalAreDropped) {
  std::ostringstream stream;
  ProgressLine line(stream, true, std::chrono::hours(1));
  line.update("first");
  line.update("second");
  EXPECT_EQ(visible(stream.str()), "first");
}

TEST(Progress, OffWritesNothing) {
  std::ostringstream stream;
  {
    ProgressLine line(stream, false);
    EXPECT_FALSE(line.enabled());
    line.set_prefix("case 1/2");
    line.update("forward run 1");
    line.update("sample", 1, 10);
    std::unique_ptr<Mission> mission = ground::make_mission();
    OptimizerProgress observer(line, *mission);
    observer.on_forward_run(record(3, 280.0, true), OptimizerResult{});
    line.clear();
  }
  EXPECT_TRUE(stream.str().empty());
  EXPECT_FALSE(ground::progress_enabled(ProgressMode::kOff));
  EXPECT_TRUE(ground::progress_enabled(ProgressMode::kOn));
}

TEST(Progress, OptimizerObserverReportsEachForwardRun) {
  std::ostringstream stream;
  std::unique_ptr<Mission> mission = ground::make_mission();  // IP(1) = 0: payload payoff, lb
  {
    ProgressLine line(stream, true, std::chrono::steady_clock::duration::zero());
    OptimizerProgress observer(line, *mission);
    observer.on_forward_run(record(1, 250.0, false), OptimizerResult{});
    EXPECT_EQ(visible(stream.str()), "forward run 1  payoff 250.0 lb  unsuccessful");
    observer.on_forward_run(record(7, 301.24, true), OptimizerResult{});
    EXPECT_EQ(visible(stream.str()), "forward run 7  payoff 301.2 lb  successful");
  }
  EXPECT_EQ(visible(stream.str()), "") << "the destructor clears the line";
}

TEST(Progress, ForcedOnThroughTheOptimizeCommand) {
  const std::string deck = std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.toml";
  ground::OptimizeCommandOptions options;
  options.deck_path = deck;
  options.json = true;
  options.progress = ProgressMode::kOn;
  std::ostringstream out;
  std::ostringstream err;
  ground::run_optimize_command(options, out, err);
  EXPECT_TRUE(contains(err.str(), "\rforward run 1  payoff 250.0 lb")) << err.str().substr(0, 300);
  // The deck's input warnings come first; the progress line is cleared before anything after it.
  const std::string after_warnings = without_input_warnings(err.str());
  EXPECT_EQ(visible(after_warnings.substr(0, after_warnings.find('\n'))), "")
      << "cleared before anything else";
  EXPECT_EQ(out.str().find('\r'), std::string::npos) << "never on stdout";
}

TEST(Progress, OptimizeIsSilentWhenStderrIsNotATerminal) {
  // Under CTest stderr is a file: the default (auto) shows nothing, and --no-progress never does.
  const std::string deck = std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.toml";
  for (const char* flag : {"--json", "--no-progress"}) {
    const CommandResult result = run_tolip_executable({"optimize", deck, "--json", flag});
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err.find('\r'), std::string::npos) << flag << ": " << result.err.substr(0, 200);
    EXPECT_FALSE(contains(result.err, "forward run")) << flag;
  }
  const CommandResult forced = run_tolip_executable({"optimize", deck, "--json", "--progress"});
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_TRUE(contains(forced.err, "\rforward run 1  payoff 250.0 lb")) << forced.err.substr(0, 200);
}

}  // namespace
}  // namespace tolip::test
