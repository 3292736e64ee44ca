// The one-line progress display (progress.hpp).
#include "tolip_ground/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "tolip_ground/optimization_report.hpp"

namespace tolip::ground {
namespace {

// Longer lines would wrap on an 80-column terminal, and a carriage return only goes back to the
// start of the last screen row, so the next update would not overwrite the first.
constexpr std::size_t kMaxLineWidth = 79;

}  // namespace

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

bool progress_enabled(ProgressMode mode) {
  switch (mode) {
    case ProgressMode::kOn: return true;
    case ProgressMode::kOff: return false;
    case ProgressMode::kAuto: return stderr_is_terminal();
  }
  return false;
}

ProgressLine::ProgressLine(std::ostream& stream, bool enabled,
                           std::chrono::steady_clock::duration min_interval)
    : stream_(stream), enabled_(enabled), min_interval_(min_interval) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::set_prefix(std::string prefix) { prefix_ = std::move(prefix); }

void ProgressLine::update(std::string_view text) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (shown_any_ && now - last_update_ < min_interval_) return;
  shown_any_ = true;
  last_update_ = now;

  std::string line = prefix_;
  if (!line.empty() && !text.empty()) line += "  ";
  line += text;
  if (line.size() > kMaxLineWidth) line.resize(kMaxLineWidth);
  // Pad over what is left of a longer previous line instead of an ANSI erase: works on any
  // terminal (and in an Emacs shell buffer).
  const std::size_t pad = visible_ > line.size() ? visible_ - line.size() : 0;
  stream_ << '\r' << line << std::string(pad, ' ');
  if (pad > 0) stream_ << '\r' << line;
  stream_.flush();
  visible_ = line.size();
}

void ProgressLine::update(std::string_view what, long count, long total, std::string_view detail) {
  if (!enabled_) return;
  std::string text(what);
  text += ' ' + std::to_string(count);
  if (total > 0) {
    const long percent = std::lround(100.0 * static_cast<double>(count) / static_cast<double>(total));
    text += '/' + std::to_string(total) + " (" + std::to_string(percent) + "%)";
  }
  if (!detail.empty()) {
    text += "  ";
    text += detail;
  }
  update(text);
}

void ProgressLine::clear() {
  if (!enabled_ || visible_ == 0) return;
  stream_ << '\r' << std::string(visible_, ' ') << '\r';
  stream_.flush();
  visible_ = 0;
  shown_any_ = false;  // the next task's first update shows at once
}

std::string optimizer_progress_text(const IterationRecord& record, const char* payoff_unit) {
  char payoff[64];
  if (std::isfinite(record.payoff)) {
    std::snprintf(payoff, sizeof payoff, "payoff %.1f %s", record.payoff, payoff_unit);
  } else {
    std::snprintf(payoff, sizeof payoff, "payoff - %s", payoff_unit);
  }
  return "forward run " + std::to_string(record.forward_run) + "  " + payoff + "  " +
         (record.successful ? "successful" : "unsuccessful") +
         (ok(record.run_status) ? std::string() : std::string(" (") + status_name(record.run_status) + ")");
}

OptimizerProgress::OptimizerProgress(ProgressLine& line, const Mission& mission)
    : line_(line), unit_(payoff_unit(mission.options.payoff())) {}

void OptimizerProgress::on_forward_run(const IterationRecord& record, const OptimizerResult& /*result*/) {
  line_.update(optimizer_progress_text(record, unit_));
}

}  // namespace tolip::ground
