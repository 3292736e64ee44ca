// Drawing figures into files (tolip_ground/plot_files.hpp).
#include "tolip_ground/plot_files.hpp"

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

}  // namespace

// DIR made when missing, and writable. Checked before gnuplot runs, so the error comes at once.
bool prepare_output_directory(const std::string& dir, std::string* error) {
  if (dir.empty()) {
    *error = "the output directory is empty";
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

bool draw_figures(const std::vector<Figure>& figures, const std::string& gnuplot,
                  std::vector<DrawnImage>* images, std::string* error) {
  images->clear();
  WorkDirectory work;
  if (work.path().empty()) {
    *error = work.error();
    return false;
  }
  const std::string program = gnuplot_program(gnuplot);
  std::vector<PlotOutput> outputs;
  try {
    const std::string script = write_gnuplot_files(figures, work.path(), &outputs);
    if (!run_gnuplot(program, work.path(), script, error)) return false;
  } catch (const std::runtime_error& e) {
    *error = e.what();
    return false;
  }
  for (const PlotOutput& output : outputs) {
    DrawnImage image;
    image.file_name = output.file_name;
    const std::string drawn = work.path() + "/" + output.file_name;
    std::string read_error;
    if (!read_file_capped(drawn, kMaxResultFileBytes, "drawn image", &image.bytes, &read_error) ||
        !looks_like_image(image.bytes, output.png)) {
      *error = std::string("gnuplot did not produce a complete ") + (output.png ? "PNG" : "SVG") +
               " image '" + output.file_name + "'";
      return false;
    }
    images->push_back(std::move(image));
  }
  return true;
}

bool write_drawn_images(const std::string& dir, const std::vector<DrawnImage>& images, std::ostream* out,
                        std::string* error) {
  for (const DrawnImage& image : images) {
    const std::string target = (fs::path(dir) / image.file_name).string();
    if (!write_file_atomically(target, image.bytes, error)) return false;
    if (out != nullptr) *out << "wrote " << target << " (" << image.bytes.size() << " bytes)\n";
  }
  return true;
}

}  // namespace tolip::ground
