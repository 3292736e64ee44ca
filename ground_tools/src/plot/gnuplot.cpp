// Drawing figures with gnuplot (plot.hpp): data files and a script in a private work directory,
// gnuplot run there as a child process, its messages kept in a log for the error report.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "tolip_ground/capped_read.hpp"
#include "tolip_ground/plot.hpp"

extern char** environ;

namespace tolip::ground {
namespace {

constexpr const char* kLogName = "gnuplot.log";
// Figure size in pixels (PNG) and in SVG user units; the font is cairo's/the viewer's sans.
constexpr const char* kSize = "size 1000,680";
constexpr const char* kFont = "font \"sans,11\"";

// A gnuplot double-quoted string: backslash and quote escaped, a newline as \n, other control
// characters dropped. The terminals run noenhanced, so ^ _ @ { } in a case title print as
// themselves.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '\\' || c == '"') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";  // a line break in a title
    } else if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) {
      out += c;
    }
  }
  return out + "\"";
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << text;
  file.close();
  if (!file) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
}

// Two columns at full precision; a blank line where a value is not finite (gnuplot breaks the
// line there).
std::string data_text(const PlotSeries& series) {
  std::string text;
  char line[80];
  bool gap = false;
  for (std::size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
    if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) {
      if (!gap && !text.empty()) text += '\n';
      gap = true;
      continue;
    }
    gap = false;
    std::snprintf(line, sizeof line, "%.17g %.17g\n", series.x[i], series.y[i]);
    text += line;
  }
  return text;
}

// The commands drawing one figure on the current terminal; data files by name.
std::string figure_commands(const Figure& figure, const std::string& case_title,
                            const std::vector<std::string>& data_files) {
  std::ostringstream script;
  script << "reset\n"
         << "set title " << quoted(case_title.empty() ? figure.title : figure.title + "\n" + case_title) << '\n'
         << "set xlabel " << quoted(figure.x_label) << '\n'
         << "set ylabel " << quoted(figure.y_label) << '\n'
         << "set grid\n"
         << "set key outside below\n"
         << "set format \"%.7g\"\n";  // 1800000, not 1.8e+06
  script << "plot ";
  bool first = true;
  for (std::size_t i = 0; i < figure.series.size(); ++i) {
    const PlotSeries& series = figure.series[i];
    if (!first) script << ", \\\n     ";
    first = false;
    script << quoted(data_files[i]) << " using 1:2";
    if (series.style == SeriesStyle::kPoints) {
      script << " with points pt 7 ps 0.6";
    } else {
      script << " with lines lw 2" << (series.dashed ? " dt 2" : "");
    }
    script << " lc " << (i + 1) << " title " << quoted(series.title);
  }
  script << '\n';
  return script.str();
}

}  // namespace

std::string write_gnuplot_files(const std::vector<Figure>& figures, const std::string& suffix,
                                const std::string& case_title, const std::string& work_dir,
                                std::vector<PlotOutput>* outputs) {
  std::ostringstream script;
  script << "# Written by tolip plot: one PNG and one SVG per figure.\n"
         << "set encoding utf8\n";
  for (const Figure& figure : figures) {
    const std::string stem = figure.name + suffix;
    std::vector<std::string> data_files;
    for (std::size_t i = 0; i < figure.series.size(); ++i) {
      const std::string name = stem + "." + std::to_string(i + 1) + ".dat";
      write_text(work_dir + "/" + name, data_text(figure.series[i]));
      data_files.push_back(name);
    }
    const std::string commands = figure_commands(figure, case_title, data_files);
    script << "\nset terminal pngcairo " << kSize << " noenhanced " << kFont << "\n"
           << "set output " << quoted(stem + ".png") << '\n'
           << commands << "unset output\n"
           << "set terminal svg " << kSize << " noenhanced " << kFont << " background \"white\"\n"
           << "set output " << quoted(stem + ".svg") << '\n'
           << commands << "unset output\n";
    outputs->push_back({stem + ".png", true});
    outputs->push_back({stem + ".svg", false});
  }
  const std::string script_name = "plots" + suffix + ".gp";
  write_text(work_dir + "/" + script_name, script.str());
  return script_name;
}

std::string gnuplot_program(const std::string& requested) {
  if (!requested.empty()) return requested;
  const char* from_environment = std::getenv("TOLIP_GNUPLOT");
  if (from_environment != nullptr && *from_environment != '\0') return from_environment;
  return "gnuplot";
}

bool run_gnuplot(const std::string& program, const std::string& work_dir, const std::string& script_name,
                 std::string* error) {
  const std::string log_path = work_dir + "/" + kLogName;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addchdir_np(&actions, work_dir.c_str());

  std::string arg0 = program;
  std::string arg1 = script_name;
  char* argv[] = {arg0.data(), arg1.data(), nullptr};
  pid_t pid = -1;
  const int spawn_error = ::posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error != 0) {
    *error = "cannot run gnuplot ('" + program + "'): " + std::strerror(spawn_error) +
             "; install the Debian package gnuplot-nox (scripts/setup.sh does) or name the program with "
             "--gnuplot or TOLIP_GNUPLOT";
    return false;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      *error = std::string("cannot wait for gnuplot: ") + std::strerror(errno);
      return false;
    }
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;

  // The end of gnuplot's messages says which line of the script it stopped at.
  std::string messages;
  std::string ignored;
  if (!read_file_capped(log_path, std::size_t{1} << 20, "gnuplot log", &messages, &ignored)) messages.clear();
  while (!messages.empty() && (messages.back() == '\n' || messages.back() == ' ')) messages.pop_back();
  if (messages.size() > 600) messages = "..." + messages.substr(messages.size() - 600);
  const std::string how = WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                            : "signal " + std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  *error = "gnuplot ('" + program + "') failed (" + how + ")" + (messages.empty() ? "" : ": " + messages);
  return false;
}

bool looks_like_image(const std::string& bytes, bool png) {
  if (png) {
    static const char kSignature[] = "\x89PNG\r\n\x1a\n";
    return bytes.size() > 20 && bytes.compare(0, 8, kSignature, 8) == 0 &&
           bytes.find("IEND", bytes.size() - 12) != std::string::npos;
  }
  return bytes.find("<svg") != std::string::npos && bytes.find("</svg>") != std::string::npos;
}

}  // namespace tolip::ground
