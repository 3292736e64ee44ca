// Plots of a result (`tolip plot RESULT.json --out DIR`): PNG and SVG figures of the JSON that
// `tolip simulate --json` and `tolip optimize --json` print, drawn by gnuplot (Debian package
// gnuplot-nox, installed by scripts/setup.sh). TOLIP writes data and a script; gnuplot renders.
//
// Every plot is a small function keyed on the top-level JSON member it needs: a document without
// that member (or with it empty) simply does not get the plot. So a plot arrives with its
// analysis: the dispersion summary (member "dispersion"), the impact locus on a map grid
// ("impact") and radar azimuth/elevation vs time ("radar") are added to plot_catalogue() when
// those analyses put their members in the JSON. docs/cli.md ("tolip plot") lists the plots.
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tolip::ground {

// A malformed result: `what()` names the field, e.g.
// "trajectory[15].altitude_ft: expected a number or null, found string".
class PlotDataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class SeriesStyle { kLines, kPoints };

// One curve. A non-finite x or y is a gap: the line is broken there (a JSON null).
struct PlotSeries {
  std::string title;  // legend entry
  SeriesStyle style = SeriesStyle::kLines;
  bool dashed = false;
  std::vector<double> x;
  std::vector<double> y;  // same length as x
};

// One figure: one PNG and one SVG named after `name`.
struct Figure {
  std::string name;      // file stem, e.g. "altitude_downrange"
  std::string title;     // first title line; the case title (data block 1) follows
  std::string x_label;   // with its unit: "downrange (n.mi.)"
  std::string y_label;
  std::vector<PlotSeries> series;
};

// One plot of the catalogue.
struct PlotKind {
  const char* name;         // Figure::name
  const char* member;       // the top-level JSON member it needs
  const char* description;  // for docs and --help
  // The figure of one document; nullopt when the member is absent or holds nothing to plot.
  // Throws PlotDataError when the member is there but malformed.
  std::optional<Figure> (*build)(const nlohmann::json& document);
};

// Every plot, in the order they are drawn.
std::span<const PlotKind> plot_catalogue();

// The largest magnitude drawn: a value beyond it (1e308, a diverged run) is drawn as a gap, like
// a JSON null; gnuplot cannot scale an axis to it.
inline constexpr double kMaxPlotMagnitude = 1e30;

// The figures of one result document (a JSON object) and the names of the catalogue plots skipped
// for want of data. A figure whose data hold no drawable value (every value null, or beyond
// kMaxPlotMagnitude) is not drawn either: `notes` says so, naming it (tolip plot prints the notes
// on stderr); so is a curve of a figure left out for the same reason. Throws PlotDataError for a
// malformed document.
struct DocumentFigures {
  std::vector<Figure> figures;
  std::vector<std::string> skipped;  // "name (no member 'linearized')"
  std::vector<std::string> notes;    // "figure altitude_downrange skipped: ..."
};
DocumentFigures figures_for_document(const nlohmann::json& document);

// ---- gnuplot ------------------------------------------------------------------------------------

// One output file of a figure.
struct PlotOutput {
  std::string file_name;  // "altitude_downrange.case2.png"
  bool png = false;       // else SVG
};

// Writes the data files and the gnuplot script that draw `figures` into `work_dir` (an existing,
// private directory), the outputs named "<name><suffix>.png" and ".svg" (suffix e.g. ".case2"),
// and appends the outputs to *outputs. `case_title` (data block 1; may be empty) is the second
// title line of every figure. All file names are relative to work_dir, so the script is run
// there. Returns the script's file name. Throws std::runtime_error when a file cannot be written.
std::string write_gnuplot_files(const std::vector<Figure>& figures, const std::string& suffix,
                                const std::string& case_title, const std::string& work_dir,
                                std::vector<PlotOutput>* outputs);

// The gnuplot program: `requested` when not empty, else $TOLIP_GNUPLOT when set, else "gnuplot"
// (looked up on PATH).
std::string gnuplot_program(const std::string& requested);

// Runs `program script_name` in `work_dir` (stdin /dev/null, stdout and stderr to a log file
// there). Returns false and sets *error when gnuplot cannot be started (saying how to install it)
// or fails (with the end of its messages).
bool run_gnuplot(const std::string& program, const std::string& work_dir, const std::string& script_name,
                 std::string* error);

// Whether `bytes` look like a complete image of the kind: the PNG signature and IEND chunk, or
// an SVG document with an <svg element and its end tag.
bool looks_like_image(const std::string& bytes, bool png);

}  // namespace tolip::ground
