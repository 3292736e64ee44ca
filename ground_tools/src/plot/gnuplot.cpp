// Drawing figures with gnuplot (plot.hpp): data files and a script in a private work directory,
// gnuplot run there as a child process, its messages kept in a log for the error report.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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
std::string gnuplot_string(const std::string& text) {
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

// A number for the script: full precision, never NaN (callers skip non-finite values).
std::string num(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

bool drawable(double value) { return std::fabs(value) <= kMaxPlotMagnitude; }

// The palette of the curves (colour-blind safe, readable on white; gnuplot's default 5 is yellow).
constexpr const char* kPalette[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                    "#e69f00", "#56b4e9", "#000000", "#808080"};
constexpr int kPaletteSize = 8;
std::string palette_color(int index) {
  return std::string("rgb \"") + kPalette[(index - 1 + kPaletteSize) % kPaletteSize] + "\"";
}

// The range of the x values drawn (the figure's own range when it sets one).
void x_extent(const Figure& figure, double* low, double* high) {
  *low = figure.x_min;
  *high = figure.x_max;
  double data_low = HUGE_VAL;
  double data_high = -HUGE_VAL;
  for (const PlotSeries& series : figure.series) {
    for (const double x : series.x) {
      if (std::isfinite(x)) {
        data_low = std::min(data_low, x);
        data_high = std::max(data_high, x);
      }
    }
  }
  if (!std::isfinite(*low)) *low = data_low;
  if (!std::isfinite(*high)) *high = data_high;
}

std::string style_text(SeriesStyle style, int color, int dash_type, int point_type) {
  std::string text;
  switch (style) {
    case SeriesStyle::kPoints: text = " with points pt " + std::to_string(point_type) + " ps 1.1"; break;
    case SeriesStyle::kLinesPoints:
      text = " with linespoints lw 2 pt " + std::to_string(point_type) + " ps 0.9 dt " +
             std::to_string(dash_type);
      break;
    case SeriesStyle::kLines: text = " with lines lw 2 dt " + std::to_string(dash_type); break;
  }
  return text + " lc " + (color == 0 ? std::string("rgb \"black\"") : palette_color(color));
}

// The commands drawing one figure on the current terminal; data files by name.
std::string figure_commands(const Figure& figure, const std::vector<std::string>& data_files) {
  std::string title = figure.title;
  for (const std::string& line : figure.subtitle) {
    if (!line.empty()) title += "\n" + line;
  }
  std::ostringstream script;
  script << "reset\n"
         << "set title " << gnuplot_string(title) << '\n'
         << "set xlabel " << gnuplot_string(figure.x_label) << '\n'
         << "set ylabel " << gnuplot_string(figure.y_label) << '\n'
         << "set grid\n"
         << "set key outside below\n"
         << "set format \"%.7g\"\n";  // 1800000, not 1.8e+06
  if (!figure.y2_label.empty()) {
    script << "set y2label " << gnuplot_string(figure.y2_label) << "\nset ytics nomirror\nset y2tics\n"
           << "set format y2 \"%.7g\"\n";
  }
  if (figure.y_log) script << "set logscale y\n";
  if (figure.y2_log) script << "set logscale y2\n";
  if (figure.equal_axis_scale) {
    script << "set size ratio -1\n";
  } else if (std::isfinite(figure.aspect_ratio)) {
    script << "set size ratio " << num(figure.aspect_ratio) << '\n';
  }
  if (std::isfinite(figure.y_min) && std::isfinite(figure.y_max)) {
    script << "set yrange [" << num(figure.y_min) << ":" << num(figure.y_max) << "]\n";
  }
  if (!figure.x_markers.empty() || !figure.points.empty()) {
    script << "set offsets 0, 0, graph 0.16, 0\n";  // headroom for the markers' labels
  }
  double low = 0.0;
  double high = 0.0;
  x_extent(figure, &low, &high);
  if (std::isfinite(figure.x_min) || std::isfinite(figure.x_max)) {
    script << "set xrange [" << (std::isfinite(figure.x_min) ? num(figure.x_min) : "*") << ":"
           << (std::isfinite(figure.x_max) ? num(figure.x_max) : "*") << "]\n";
  }
  const bool have_extent = std::isfinite(low) && std::isfinite(high);
  const auto inside = [&](double x) { return drawable(x) && have_extent && x >= low && x <= high; };

  // Shaded intervals, clipped to the range drawn.
  int object = 0;
  for (const XBand& band : figure.bands) {
    if (!drawable(band.from) || !drawable(band.to) || !have_extent) continue;
    const double from = std::max(band.from, low);
    const double to = std::min(band.to, high);
    if (!(to > from)) continue;
    script << "set object " << ++object << " rectangle from first " << num(from) << ", graph 0 to first "
           << num(to)
           << ", graph 1 back fillcolor rgb \"#7fb2e5\" fillstyle transparent solid 0.30 noborder\n";
  }

  // Vertical markers: a line each; markers closer than 2% of the range share one label, joined.
  std::vector<const XMarker*> markers;
  for (const XMarker& marker : figure.x_markers) {
    if (inside(marker.x)) markers.push_back(&marker);
  }
  std::stable_sort(markers.begin(), markers.end(),
                   [](const XMarker* a, const XMarker* b) { return a->x < b->x; });
  const double close = 0.02 * (high - low);
  int label_number = 0;
  for (std::size_t i = 0; i < markers.size();) {
    std::size_t j = i;
    std::string text;
    while (j < markers.size() && markers[j]->x - markers[i]->x <= close) {
      const XMarker& marker = *markers[j];
      script << "set arrow from first " << num(marker.x) << ", graph 0 to first " << num(marker.x)
             << ", graph 1 nohead back lw 1 dt 3 lc "
             << palette_color(marker.color == 0 ? kMarkerGrey : marker.color) << '\n';
      if (!marker.label.empty()) text += (text.empty() ? "" : ", ") + marker.label;
      ++j;
    }
    if (!text.empty()) {
      script
          << "set label " << ++label_number << ' ' << gnuplot_string(text) << " at first "
          << num(markers[i]->x)
          << ", graph 0.98 right rotate by 90 offset character -0.2, 0 font \",9\" textcolor rgb \"#404040\" "
             "front\n";
    }
    i = j;
  }
  // Points: a dot each; points within 3% of the ranges of one another share the first one's label.
  double y_low = HUGE_VAL;
  double y_high = -HUGE_VAL;
  for (const PlotSeries& series : figure.series) {
    if (series.second_axis) continue;
    for (const double y : series.y) {
      if (std::isfinite(y)) {
        y_low = std::min(y_low, y);
        y_high = std::max(y_high, y);
      }
    }
  }
  std::vector<std::string> point_labels;
  std::vector<const PointMarker*> labelled;
  for (const PointMarker& point : figure.points) {
    if (!inside(point.x) || !drawable(point.y)) continue;
    std::size_t near = labelled.size();
    for (std::size_t k = 0; k < labelled.size(); ++k) {
      if (std::fabs(labelled[k]->x - point.x) <= 0.03 * (high - low) &&
          std::fabs(labelled[k]->y - point.y) <= 0.03 * (y_high - y_low)) {
        near = k;
        break;
      }
    }
    if (near < labelled.size()) {
      if (!point.label.empty()) point_labels[near] += (point_labels[near].empty() ? "" : ", ") + point.label;
    } else {
      labelled.push_back(&point);
      point_labels.push_back(point.label);
    }
    script << "set label " << ++label_number << " \"\" at first " << num(point.x) << ", first "
           << num(point.y) << " point pointtype 7 pointsize 1.4 linecolor "
           << (point.color == 0 ? std::string("rgb \"black\"") : palette_color(point.color)) << " front\n";
  }
  for (std::size_t k = 0; k < labelled.size(); ++k) {
    if (point_labels[k].empty()) continue;
    const bool right_quarter = labelled[k]->x > low + 0.75 * (high - low);
    script << "set label " << ++label_number << ' ' << gnuplot_string(point_labels[k]) << " at first "
           << num(labelled[k]->x) << ", first " << num(labelled[k]->y)
           << (right_quarter ? " right offset character -0.9, 0.9" : " left offset character 0.9, 0.9")
           << " font \",9\" front\n";
  }
  for (const YLine& line : figure.y_lines) {
    const char* axis = line.second_axis ? "second" : "first";
    script << "set arrow from graph 0, " << axis << ' ' << num(line.y) << " to graph 1, " << axis << ' '
           << num(line.y) << " nohead front lw 1.5 dt 2 lc rgb \"#404040\"\n";
    if (!line.label.empty()) {
      script << "set label " << ++label_number << ' ' << gnuplot_string(line.label) << " at graph 0.01, "
             << axis << ' ' << num(line.y) << " offset 0, character 0.6 font \",9\" front\n";
    }
  }

  script << "plot ";
  bool first = true;
  const auto next = [&] {
    if (!first) script << ", \\\n     ";
    first = false;
  };
  if (!figure.bands.empty() && !figure.band_title.empty() && object > 0) {
    next();
    script << "keyentry with boxes fillcolor rgb \"#7fb2e5\" fillstyle transparent solid 0.30 noborder title "
           << gnuplot_string(figure.band_title);
  }
  for (const KeyEntry& entry : figure.key_entries) {
    next();
    script << "keyentry" << style_text(entry.style, entry.color, entry.dash_type, entry.point_type)
           << " title " << gnuplot_string(entry.title);
  }
  for (std::size_t i = 0; i < figure.series.size(); ++i) {
    const PlotSeries& series = figure.series[i];
    next();
    const int dash = series.dash_type != 0 ? series.dash_type : (series.dashed ? 2 : 1);
    const int color = series.color != 0 ? series.color : static_cast<int>(i % kPaletteSize) + 1;
    script << gnuplot_string(data_files[i]) << " using 1:2" << (series.second_axis ? " axes x1y2" : "")
           << style_text(series.style, color, dash, series.point_type)
           << (series.title.empty() ? std::string(" notitle") : " title " + gnuplot_string(series.title));
  }
  script << '\n';
  return script.str();
}

}  // namespace

std::string write_gnuplot_files(const std::vector<Figure>& figures, const std::string& work_dir,
                                std::vector<PlotOutput>* outputs) {
  std::ostringstream script;
  script << "# Written by tolip plot: one PNG and one SVG per figure.\n"
         << "set encoding utf8\n";
  for (const Figure& figure : figures) {
    const std::string& stem = figure.name;
    std::vector<std::string> data_files;
    for (std::size_t i = 0; i < figure.series.size(); ++i) {
      const std::string name = stem + "." + std::to_string(i + 1) + ".dat";
      write_text(work_dir + "/" + name, data_text(figure.series[i]));
      data_files.push_back(name);
    }
    const std::string commands = figure_commands(figure, data_files);
    script << "\nset terminal pngcairo " << kSize << " noenhanced " << kFont << "\n"
           << "set output " << gnuplot_string(stem + ".png") << '\n'
           << commands << "unset output\n"
           << "set terminal svg " << kSize << " noenhanced " << kFont << " background \"white\"\n"
           << "set output " << gnuplot_string(stem + ".svg") << '\n'
           << commands << "unset output\n";
    outputs->push_back({stem + ".png", true});
    outputs->push_back({stem + ".svg", false});
  }
  const std::string script_name = "plots.gp";
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
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0600);
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
  const std::string how = WIFEXITED(status)
                              ? "exit code " + std::to_string(WEXITSTATUS(status))
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
