// Drawing figures into files (`tolip plot`, `tolip montecarlo --plots`): DIR made and checked
// first, everything drawn by gnuplot and checked in a private temporary directory, and only then
// each image written into DIR atomically, so a failure leaves DIR as it was.
#pragma once

#include <string>
#include <vector>

#include "tolip_ground/plot.hpp"

namespace tolip::ground {

// DIR made when missing, and writable; false with *error otherwise (checked before gnuplot runs,
// so the error comes at once).
bool prepare_output_directory(const std::string& dir, std::string* error);

// One drawn image.
struct DrawnImage {
  std::string file_name;  // "altitude_downrange.png"
  std::string bytes;
};

// Draws `figures` (PNG and SVG each) with the gnuplot program (gnuplot_program()) in a temporary
// directory, reads and checks every image; false with *error when gnuplot is missing or fails or an
// image is incomplete. Nothing outside the temporary directory is touched.
bool draw_figures(const std::vector<Figure>& figures, const std::string& gnuplot,
                  std::vector<DrawnImage>* images, std::string* error);

// Writes every image into DIR atomically, one line "wrote DIR/NAME (N bytes)" each on `out` when not
// null; false with *error at the first failure.
bool write_drawn_images(const std::string& dir, const std::vector<DrawnImage>& images, std::ostream* out,
                        std::string* error);

}  // namespace tolip::ground
