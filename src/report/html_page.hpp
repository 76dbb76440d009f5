// The pieces every section of the HTML report shares: text escaping, base64, and the page being written
// (its body so far and the PNG figures it embeds as data URIs).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace t2imu {

std::string base64(const std::vector<uint8_t>& bytes);
// Escapes < > & " for HTML text and attribute values.
std::string html_escape(const std::string& s);

struct Page {
    std::string body;     // HTML inside <body>
    std::string out_dir;  // the report folder: figures are drawn here
    int figures = 0;

    // Embeds `out_dir/png_name` (already drawn) with a caption.
    void figure(const std::string& png_name, const std::string& caption);
};

}  // namespace t2imu
