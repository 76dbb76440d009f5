#include "report/html_page.hpp"

#include "core/atomic_file.hpp"

namespace t2imu {

std::string base64(const std::vector<uint8_t>& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t b = (uint32_t{bytes[i]} << 16) | (i + 1 < bytes.size() ? uint32_t{bytes[i + 1]} << 8 : 0u) |
                           (i + 2 < bytes.size() ? uint32_t{bytes[i + 2]} : 0u);
        out += table[(b >> 18) & 63];
        out += table[(b >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(b >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? table[b & 63] : '=';
    }
    return out;
}

std::string html_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

void Page::figure(const std::string& png_name, const std::string& caption) {
    const std::string path = out_dir + "/" + png_name;
    body += "<figure><img src=\"data:image/png;base64," + base64(read_file_bytes(path)) + "\" alt=\"" +
            html_escape(caption) + "\"><figcaption>" + html_escape(caption) + "</figcaption></figure>\n";
    ++figures;
}

}  // namespace t2imu
