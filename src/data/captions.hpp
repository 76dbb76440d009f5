// HumanML3D caption files (texts/ID.txt): one caption per line, `caption#tokens#start#end`, where tokens are
// `word/POS` pairs (may be empty) and start/end are seconds into the clip; 0.0#0.0 means the whole clip.
#pragma once
#include <string>
#include <vector>

namespace t2imu {

struct CaptionLine {
    std::string caption;
    std::string tokens;
    double start_s = 0;
    double end_s = 0;
    bool whole_clip() const { return start_s == 0 && end_s == 0; }
};

CaptionLine parse_caption_line(const std::string& line, const std::string& source);
std::vector<CaptionLine> read_caption_file(const std::string& path);  // blank lines skipped
// The captions of a corpus: every *.txt of a folder (a HumanML3D texts/, in name order) or one caption file;
// Error naming `path` when there is none.
std::vector<std::string> read_caption_corpus(const std::string& path);
std::string format_caption_line(const CaptionLine& c);  // tags with one decimal, as HumanML3D writes them

// "left" <-> "right" as whole words (any case kept: Left -> Right, LEFT -> RIGHT), for mirrored motions.
std::string swap_left_right(const std::string& caption);

}  // namespace t2imu
