// PNG figures drawn by gnuplot (Debian's gnuplot-nox, pngcairo terminal). A figure is a gnuplot script plus
// the data blocks it plots; the script is piped to `gnuplot` (or $T2IMU_GNUPLOT), so nothing but the PNG is
// written. Data blocks are gnuplot's inline "$name << EOD" heredocs, so no temporary files either.
#pragma once
#include <string>
#include <vector>

namespace t2imu {

struct GnuplotData {
    std::string name;                            // used as $name in the script
    std::vector<std::vector<std::string>> rows;  // whitespace-free fields (quote labels with spaces)
};

// Renders `script` (which must not set terminal or output) to `png_path`, width x height pixels. Throws Error
// with gnuplot's message when it fails or is missing.
void render_png(const std::string& png_path, const std::vector<GnuplotData>& data, const std::string& script,
                int width = 900, int height = 560);

// Quotes a label for a gnuplot script or data block, with the characters of enhanced text (_ ^ { } @) escaped.
std::string gnuplot_label(const std::string& s);

}  // namespace t2imu
