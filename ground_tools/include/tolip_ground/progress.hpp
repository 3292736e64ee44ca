// A one-line progress display for long runs (optimization forward runs now; dispersions and Monte
// Carlo samples later): "case 2/3  forward run 7  payoff 301.2 lb  successful", rewritten in place
// with a carriage return on a terminal, nothing at all otherwise.
//
// Progress is a courtesy to a person watching, never part of the output: it goes to stderr only,
// only when stderr is a terminal (or the user forces it), so logs, pipes, CI and tests see exactly
// the same bytes as before. docs/cli.md ("Progress display").
#pragma once

#include <chrono>
#include <ostream>
#include <string>
#include <string_view>

#include "tolip/mission/mission.hpp"
#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip::ground {

// --progress / --no-progress / neither.
enum class ProgressMode { kAuto, kOn, kOff };

// True when file descriptor 2 is a terminal.
bool stderr_is_terminal();

// Whether a display in `mode` shows anything: kAuto follows stderr_is_terminal().
bool progress_enabled(ProgressMode mode);

// The status line. Not thread-safe; one per command run. A disabled line writes nothing, ever.
class ProgressLine {
 public:
  // `min_interval`: updates closer together than this are dropped (a Monte Carlo run may report
  // thousands a second; a terminal needs a few). The first update is always shown.
  explicit ProgressLine(std::ostream& stream, bool enabled,
                        std::chrono::steady_clock::duration min_interval = std::chrono::milliseconds(50));
  ~ProgressLine();  // clear()
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool enabled() const { return enabled_; }

  // Text put before every update, e.g. "case 2/3" for a deck of several cases; "" for none.
  void set_prefix(std::string prefix);

  // Replaces the line by `text` (after the prefix).
  void update(std::string_view text);

  // The count/total form for any loop: "<what> <count>/<total> (<percent>%)  <detail>", or
  // "<what> <count>  <detail>" when the total is unknown (total <= 0).
  void update(std::string_view what, long count, long total, std::string_view detail = {});

  // Erases the line (spaces over it, then a carriage return), so the next message to the stream
  // starts on a clean line. Call before writing anything else to the stream; harmless when the
  // line is already clear.
  void clear();

 private:
  std::ostream& stream_;
  bool enabled_;
  std::chrono::steady_clock::duration min_interval_;
  std::chrono::steady_clock::time_point last_update_{};
  bool shown_any_ = false;
  std::size_t visible_ = 0;  // characters of the line on screen now
  std::string prefix_;
};

// The optimizer's forward runs on a ProgressLine: "forward run 7  payoff 301.2 lb  successful".
class OptimizerProgress final : public OptimizerObserver {
 public:
  // `mission`: the case being optimized (its IP(1) names the payoff unit).
  OptimizerProgress(ProgressLine& line, const Mission& mission);
  void on_forward_run(const IterationRecord& record, const OptimizerResult& result) override;

 private:
  ProgressLine& line_;
  const char* unit_;
};

// The text of one optimizer update (for the line, and for tests).
std::string optimizer_progress_text(const IterationRecord& record, const char* payoff_unit);

}  // namespace tolip::ground
