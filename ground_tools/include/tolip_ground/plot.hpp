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

#include <limits>
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

enum class SeriesStyle { kLines, kPoints, kLinesPoints };

// One curve. A non-finite x or y is a gap: the line is broken there (a JSON null).
struct PlotSeries {
  std::string title;  // legend entry; empty: none
  SeriesStyle style = SeriesStyle::kLines;
  bool dashed = false;
  int dash_type = 0;         // gnuplot dash type when not 0 (overrides `dashed`)
  int color = 0;             // palette index 1-8; 0: the series' place in the figure
  int point_type = 7;        // gnuplot point type of kPoints and kLinesPoints (7 filled, 6 open circle)
  bool second_axis = false;  // drawn against the right-hand axis (Figure::y2_label)
  std::vector<double> x;
  std::vector<double> y;  // same length as x
};

// A vertical line across the plot at x, labelled at its top: a stage ignition or burnout. Markers
// closer than 2% of the x range share one label.
struct XMarker {
  double x = 0.0;
  std::string label;  // empty: the line only
  int color = 0;      // palette index; 0: grey (kMarkerGrey)
};

// The palette index of grey: staging lines and their legend entry.
inline constexpr int kMarkerGrey = 8;

// A point drawn as a dot and labelled beside it (to its left in the right quarter of the plot):
// max q, the launch site, a staging point. Points close together share one label.
struct PointMarker {
  double x = 0.0;
  double y = 0.0;
  std::string label;
  int color = 0;  // palette index; 0: black
};

// An x interval shaded behind the curves (the zero-alpha window); Figure::band_title names them.
struct XBand {
  double from = 0.0;
  double to = 0.0;
};

// A horizontal reference line (a deadband) across the plot.
struct YLine {
  double y = 0.0;
  bool second_axis = false;
  std::string label;
};

// A legend entry with no data of its own (in an overlay of cases: one per case, one per quantity).
struct KeyEntry {
  std::string title;
  SeriesStyle style = SeriesStyle::kLines;
  int color = 0;  // palette index; 0: black
  int dash_type = 1;
  int point_type = 7;
};

// One figure: one PNG and one SVG named after `name`.
struct Figure {
  std::string name;     // file stem, e.g. "altitude_downrange"
  std::string title;    // first title line
  std::string x_label;  // with its unit: "downrange (n.mi.)"
  std::string y_label;
  std::vector<PlotSeries> series;
  std::vector<std::string> subtitle;  // further title lines: the case title, heading and run status
  std::string y2_label;               // not empty: a right-hand axis for the series with second_axis
  bool y_log = false;
  bool y2_log = false;
  double aspect_ratio = std::numeric_limits<double>::quiet_NaN();  // plot height / width; NaN: the terminal's
  // A unit as long on x as on y (gnuplot `set size ratio -1`; aspect_ratio then unused): for a
  // scatter of positions in one unit, whose ellipses must not be drawn stretched.
  bool equal_axis_scale = false;
  double x_min = std::numeric_limits<double>::quiet_NaN();  // the ranges drawn; NaN: gnuplot's
  double x_max = std::numeric_limits<double>::quiet_NaN();
  double y_min = std::numeric_limits<double>::quiet_NaN();
  double y_max = std::numeric_limits<double>::quiet_NaN();
  std::vector<XMarker> x_markers;
  std::vector<PointMarker> points;
  std::vector<XBand> bands;
  std::string band_title;  // legend entry of the bands
  std::vector<YLine> y_lines;
  std::vector<KeyEntry> key_entries;  // drawn before the series' own entries
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

// The radar figures of a document (member "radar", docs/cli.md): one per station, "radar_<id>"
// (the identification in lower case, other characters than letters and digits as '_'): azimuth
// (deg) against time on the left axis, elevation (deg) on the right, the part below the horizon
// dashed and the horizon drawn. None when the member is absent or holds no tracked point; throws
// PlotDataError for a malformed member.
std::vector<Figure> radar_figures(const nlohmann::json& document);

// The hardover figure of a document (member "hardover", docs/cli.md): "hardover_gamma", the change
// in flight-path angle (deg) against time from the failure for every turn, a colour per stage and
// mode. None when the member is absent or holds no turn; throws PlotDataError when malformed.
std::vector<Figure> hardover_figures(const nlohmann::json& document);

// The HIL bench figures of a document (member "hil_series" of `tolip hil --json`, docs/cli.md):
// "hil_theta" (commanded and flown theta), "hil_tracking_error" (pitch and yaw), "hil_actuators"
// (fins in deg, jets in % of full force) against time. None without the member; throws
// PlotDataError when malformed.
std::vector<Figure> hil_figures(const nlohmann::json& document);
// The autopilot figures of a document (member "autopilot", docs/cli.md; issue 16):
// "autopilot_gains", K_theta (left axis) and K_q (s, right axis) against time from launch, and
// "autopilot_margins", the upper gain margin (dB, left) and the phase margin (deg, right) at the
// actuator; a break between stages. None when the member is absent or holds no point; throws
// PlotDataError when malformed.
std::vector<Figure> autopilot_figures(const nlohmann::json& document);

// The largest magnitude drawn: a value beyond it (1e308, a diverged run) is drawn as a gap, like
// a JSON null; gnuplot cannot scale an axis to it.
inline constexpr double kMaxPlotMagnitude = 1e30;

// The figures of one result document (a JSON object) and the names of the catalogue plots skipped
// for want of data. A figure whose data hold no drawable value (every value null, or beyond
// kMaxPlotMagnitude) is not drawn either: `notes` says so, naming it (tolip plot prints the notes
// on stderr); so is a curve of a figure left out for the same reason. Every figure's subtitle is
// the case title (data block 1) and the case heading (block 2) with the run status. Throws
// PlotDataError for a malformed document.
struct DocumentFigures {
  std::vector<Figure> figures;
  std::vector<std::string> skipped;  // "name (no member 'linearized')"
  std::vector<std::string> notes;    // "figure altitude_downrange skipped: ..."
};
DocumentFigures figures_for_document(const nlohmann::json& document);

// The figures of a result of one or several cases (a JSON array: a deck of several cases). One
// case: figures_for_document. Several: every case overlaid on the same figures, a colour per
// case, a legend entry per case (its heading and run status) and, where a figure has several
// curves per case, one per quantity (by dash type); the skipped plots and notes say which case
// ("... in case 2", "case 2: ..."). Throws PlotDataError naming the case ("case 2: trajectory...").
DocumentFigures figures_for_cases(const std::vector<const nlohmann::json*>& documents);

// The run status of a document for a title: "converged, kOk" or "not converged,
// kGuidanceDidNotConverge" (optimize), "simulated, kOk" (simulate); with the case's failed step
// when the case failed after a converged optimization.
std::string run_status_text(const nlohmann::json& document);

// ---- gnuplot ------------------------------------------------------------------------------------

// One output file of a figure.
struct PlotOutput {
  std::string file_name;  // "altitude_downrange.png"
  bool png = false;       // else SVG
};

// Writes the data files and the gnuplot script that draw `figures` into `work_dir` (an existing,
// private directory), the outputs named "<name>.png" and ".svg", and appends the outputs to
// *outputs. All file names are relative to work_dir, so the script is run there. Returns the
// script's file name. Throws std::runtime_error when a file cannot be written.
std::string write_gnuplot_files(const std::vector<Figure>& figures, const std::string& work_dir,
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
