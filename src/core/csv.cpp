#include "core/csv.hpp"

#include <cmath>
#include <cstdlib>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

size_t CsvTable::column(const std::string& name) const {
    for (size_t c = 0; c < header.size(); ++c)
        if (header[c] == name) return c;
    throw Error(source, "header", "a column named '" + name + "'");
}

bool CsvTable::has_column(const std::string& name) const {
    for (const std::string& h : header)
        if (h == name) return true;
    return false;
}

double CsvTable::number(size_t row, size_t col) const {
    const std::string& f = rows.at(row).at(col);
    const std::optional<double> v = parse_number(f);
    if (!v)
        throw Error(source, "row " + std::to_string(row + 2) + " column '" + header.at(col) + "'", "a number",
                    "'" + f + "'");
    return *v;
}

CsvTable parse_csv(const std::string& text, const std::string& source) {
    CsvTable t;
    t.source = source;
    std::vector<std::string> record;
    std::string field;
    bool quoted = false, field_started = false;
    int line = 1, record_line = 1;
    auto end_record = [&] {
        record.push_back(field);
        field.clear();
        field_started = false;
        if (t.header.empty()) {
            t.header = record;
        } else if (record.size() != t.header.size()) {
            throw Error(source, "line " + std::to_string(record_line),
                        std::to_string(t.header.size()) + " fields as in the header", std::to_string(record.size()));
        } else {
            t.rows.push_back(record);
        }
        record.clear();
        record_line = line;
    };
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"')
                quoted = false;
            else {
                if (c == '\n') ++line;
                field += c;
            }
            continue;
        }
        if (c == '"' && field.empty() && !field_started) {
            quoted = true;
            field_started = true;
        } else if (c == ',') {
            record.push_back(field);
            field.clear();
            field_started = false;
        } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') { /* CRLF: the \n ends the record */
        } else if (c == '\n') {
            ++line;
            end_record();
        } else {
            field += c;
            field_started = true;
        }
    }
    if (quoted) throw Error(source, "line " + std::to_string(record_line), "a closing quote", "end of file");
    if (field_started || !field.empty() || !record.empty()) end_record();
    if (t.header.empty()) throw Error(source, "header", "a header row", "an empty file");
    return t;
}

CsvTable read_csv(const std::string& path) { return parse_csv(read_file_text(path), path); }

static std::string quote(const std::string& f) {
    if (f.find_first_of(",\"\r\n") == std::string::npos) return f;
    std::string q = "\"";
    for (char c : f) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string format_csv(const CsvTable& t) {
    std::string out;
    auto row = [&](const std::vector<std::string>& r) {
        for (size_t c = 0; c < r.size(); ++c) out += (c ? "," : "") + quote(r[c]);
        out += "\n";
    };
    row(t.header);
    for (const auto& r : t.rows) row(r);
    return out;
}

void write_csv(const std::string& path, const CsvTable& t) { write_file_atomic(path, format_csv(t)); }

}  // namespace t2imu
