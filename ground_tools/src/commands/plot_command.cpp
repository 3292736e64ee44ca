// `tolip plot RESULT.json --out DIR`: the figures of a simulate/optimize JSON result as PNG and SVG
// (plot.hpp, docs/cli.md). Everything is drawn in a private temporary directory first and checked;
// only then is each file written into DIR atomically, so a failure leaves DIR as it was.
#include <ostream>
#include <string>
#include <vector>

#include "tolip_ground/capped_read.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/plot.hpp"
#include "tolip_ground/plot_files.hpp"

namespace tolip::ground {
namespace {

// nlohmann's message without its "[json.exception.parse_error.101] " tag.
std::string parse_message(const char* what) {
  std::string message = what;
  if (!message.empty() && message[0] == '[') {
    const std::size_t end = message.find("] ");
    if (end != std::string::npos) message.erase(0, end + 2);
  }
  return message;
}

// The result documents of the analyses whose figures `tolip plot` does not draw, told by their
// members (docs/cli.md): what to run instead. Null for any other document.
const char* document_without_figures(const nlohmann::json& document) {
  if (!document.is_object() || document.contains("trajectory")) return nullptr;
  if (document.contains("sampled_codes") && document.contains("staging_points")) {
    return "a 'tolip montecarlo' document holds the statistics, not the samples its figures need: "
           "they are drawn by 'tolip montecarlo DECK --samples N --seed S --plots DIR'";
  }
  if (document.contains("dispersions") && document.contains("optimizer_status")) {
    return "a 'tolip dispersions' document holds the dispersion tables, which have no figure: the "
           "final nominal's figures are drawn from 'tolip optimize DECK --json'";
  }
  return nullptr;
}

}  // namespace

int run_plot_command(const PlotCommandOptions& options, std::ostream& out, std::ostream& err) {
  const std::string& source = options.result_path;
  std::string text;
  std::string error;
  if (!read_file_capped(source, kMaxResultFileBytes, "result file", &text, &error)) {
    err << "tolip: " << source << ": " << error << '\n';
    return kExitBadInput;
  }
  nlohmann::json result;
  try {
    result = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    // parse_error, and out_of_range for a number beyond double (9.9E6033248): found by the
    // fuzz target plot_result (fuzz/regressions/plot_result/); before, the exception escaped.
    err << "tolip: " << source << ": not valid JSON: " << parse_message(e.what()) << '\n';
    return kExitBadInput;
  }

  // One document (a deck of one case) or an array of one per case, as simulate/optimize print.
  std::vector<const nlohmann::json*> documents;
  if (result.is_array()) {
    for (const nlohmann::json& document : result) documents.push_back(&document);
    if (documents.empty()) {
      err << "tolip: " << source << ": an empty array: nothing to plot\n";
      return kExitBadInput;
    }
  } else {
    documents.push_back(&result);
  }

  // Every case on the same figures (a deck of several cases: overlaid, a colour per case).
  DocumentFigures figures;
  try {
    figures = figures_for_cases(documents);
  } catch (const PlotDataError& e) {
    err << "tolip: " << source << ": " << e.what() << '\n';
    return kExitBadInput;
  }
  for (const std::string& note : figures.notes) err << "tolip: " << source << ": " << note << '\n';
  if (figures.figures.empty()) {
    err << "tolip: " << source << ": nothing to plot";
    if (const char* kind = document_without_figures(*documents[0])) {
      err << ": " << kind;
    } else if (!figures.skipped.empty()) {
      err << ": " << figures.skipped[0];
    }
    err << '\n';
    return kExitBadInput;
  }

  if (!prepare_output_directory(options.out_dir, &error)) {
    err << "tolip: " << error << '\n';
    return kExitFailure;
  }
  // Draw everything, and check it, before DIR is touched.
  std::vector<DrawnImage> images;
  if (!draw_figures(figures.figures, options.gnuplot, &images, &error) ||
      !write_drawn_images(options.out_dir, images, &out, &error)) {
    err << "tolip: " << error << '\n';
    return kExitFailure;
  }
  for (const std::string& skipped : figures.skipped) out << "skipped " << skipped << '\n';
  return kExitOk;
}

}  // namespace tolip::ground
