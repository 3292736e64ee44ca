// `tolip plot RESULT.json --out DIR`: the figures of a simulate/optimize JSON result as PNG and SVG
// (plot.hpp, docs/cli.md). Everything is drawn in a private temporary directory first and checked;
// only then is each file written into DIR atomically, so a failure leaves DIR as it was.
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/capped_read.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/plot.hpp"

namespace tolip::ground {
namespace {

namespace fs = std::filesystem;

// A fresh private directory under the system's temporary directory, removed with everything in it.
class WorkDirectory {
 public:
  WorkDirectory() {
    std::error_code ignored;
    std::string pattern = (fs::temp_directory_path(ignored) / "tolip-plot-XXXXXX").string();
    if (::mkdtemp(pattern.data()) != nullptr) path_ = pattern;
    else error_ = "cannot create a temporary directory '" + pattern + "': " + std::strerror(errno);
  }
  ~WorkDirectory() {
    std::error_code ignored;
    if (!path_.empty()) fs::remove_all(path_, ignored);
  }
  WorkDirectory(const WorkDirectory&) = delete;
  WorkDirectory& operator=(const WorkDirectory&) = delete;

  const std::string& path() const { return path_; }  // empty when it could not be made
  const std::string& error() const { return error_; }

 private:
  std::string path_;
  std::string error_;
};

// nlohmann's message without its "[json.exception.parse_error.101] " tag.
std::string parse_message(const char* what) {
  std::string message = what;
  if (!message.empty() && message[0] == '[') {
    const std::size_t end = message.find("] ");
    if (end != std::string::npos) message.erase(0, end + 2);
  }
  return message;
}

// DIR made when missing, and writable. Checked before gnuplot runs, so the error comes at once.
bool prepare_output_directory(const std::string& dir, std::string* error) {
  if (dir.empty()) {
    *error = "the output directory (--out) is empty";
    return false;
  }
  std::error_code code;
  if (!fs::exists(dir, code)) {
    fs::create_directories(dir, code);
    if (code) {
      *error = "cannot create the output directory '" + dir + "': " + code.message();
      return false;
    }
  }
  if (!fs::is_directory(dir, code)) {
    *error = "cannot write to '" + dir + "': not a directory";
    return false;
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    *error = "cannot write to '" + dir + "': " + std::strerror(errno);
    return false;
  }
  return true;
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
  } catch (const nlohmann::json::parse_error& e) {
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
    if (!figures.skipped.empty()) err << ": " << figures.skipped[0];
    err << '\n';
    return kExitBadInput;
  }

  if (!prepare_output_directory(options.out_dir, &error)) {
    err << "tolip: " << error << '\n';
    return kExitFailure;
  }

  // Draw everything, and check it, before DIR is touched.
  WorkDirectory work;
  if (work.path().empty()) {
    err << "tolip: " << work.error() << '\n';
    return kExitFailure;
  }
  const std::string program = gnuplot_program(options.gnuplot);
  std::vector<PlotOutput> outputs;
  try {
    const std::string script = write_gnuplot_files(figures.figures, work.path(), &outputs);
    if (!run_gnuplot(program, work.path(), script, &error)) {
      err << "tolip: " << error << '\n';
      return kExitFailure;
    }
  } catch (const std::runtime_error& e) {
    err << "tolip: " << e.what() << '\n';
    return kExitFailure;
  }
  std::vector<std::string> contents(outputs.size());
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string drawn = work.path() + "/" + outputs[i].file_name;
    if (!read_file_capped(drawn, kMaxResultFileBytes, "drawn image", &contents[i], &error) ||
        !looks_like_image(contents[i], outputs[i].png)) {
      err << "tolip: gnuplot did not produce a complete " << (outputs[i].png ? "PNG" : "SVG") << " image '"
          << outputs[i].file_name << "'\n";
      return kExitFailure;
    }
  }

  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string target = (fs::path(options.out_dir) / outputs[i].file_name).string();
    if (!write_file_atomically(target, contents[i], &error)) {
      err << "tolip: " << error << '\n';
      return kExitFailure;
    }
    out << "wrote " << target << " (" << contents[i].size() << " bytes)\n";
  }
  for (const std::string& skipped : figures.skipped) out << "skipped " << skipped << '\n';
  return kExitOk;
}

}  // namespace tolip::ground
