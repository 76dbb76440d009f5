#include "motion/bvh.hpp"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

namespace {

// Splits the text into whitespace-separated tokens, remembering each token's line for messages.
struct Tokens {
    std::vector<std::string> words;
    std::vector<int> lines;
    size_t i = 0;
    std::string source;

    bool done() const { return i >= words.size(); }
    int line() const { return lines.empty() ? 0 : lines[std::min(i, lines.size() - 1)]; }
    [[noreturn]] void fail(const std::string& expected) const {
        throw Error(source, "line " + std::to_string(line()), expected,
                    done() ? std::string("end of file") : "'" + words[i] + "'");
    }
    const std::string& next(const char* expected) {
        if (done()) fail(expected);
        return words[i++];
    }
    void expect(const char* word) {
        if (done() || words[i] != word) fail(std::string("'") + word + "'");
        ++i;
    }
    double number(const char* what) {
        const std::string& w = next(what);
        const std::optional<double> v = parse_finite(w);
        if (!v) {
            --i;
            fail(what);
        }
        return *v;
    }
};

Tokens tokenize(const std::string& text, const std::string& source) {
    Tokens t;
    t.source = source;
    int line = 1;
    size_t k = 0;
    while (k < text.size()) {
        const char c = text[k];
        if (c == '\n') {
            ++line;
            ++k;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            ++k;
            continue;
        }
        const size_t start = k;
        while (k < text.size() && text[k] != ' ' && text[k] != '\t' && text[k] != '\r' && text[k] != '\n') ++k;
        t.words.emplace_back(text, start, k - start);
        t.lines.push_back(line);
    }
    return t;
}

BvhChannel parse_channel(Tokens& t) {
    const std::string& w = t.next("a channel name");
    static const struct {
        const char* name;
        BvhChannel ch;
    } table[] = {{"Xposition", BvhChannel::x_position}, {"Yposition", BvhChannel::y_position},
                 {"Zposition", BvhChannel::z_position}, {"Xrotation", BvhChannel::x_rotation},
                 {"Yrotation", BvhChannel::y_rotation}, {"Zrotation", BvhChannel::z_rotation}};
    for (const auto& e : table)
        if (w == e.name) return e.ch;
    --t.i;
    t.fail("a channel name (X/Y/Zposition, X/Y/Zrotation)");
}

Eigen::Vector3d parse_offset(Tokens& t) {
    t.expect("OFFSET");
    const double x = t.number("an OFFSET number"), y = t.number("an OFFSET number"), z = t.number("an OFFSET number");
    return {x, y, z};
}

void parse_joint(Tokens& t, BvhMotion& m, const std::string& name, int parent, int depth) {
    if (depth > 256) t.fail("a hierarchy at most 256 joints deep");
    const int index = static_cast<int>(m.joints.size());
    m.joints.push_back(BvhJoint{});
    m.joints.back().name = name;
    m.joints.back().parent = parent;
    t.expect("{");
    m.joints[static_cast<size_t>(index)].offset = parse_offset(t);
    t.expect("CHANNELS");
    const double n = t.number("a channel count");
    if (n < 0 || n > 6 || n != std::floor(n)) {
        --t.i;
        t.fail("a channel count from 0 to 6");
    }
    m.joints[static_cast<size_t>(index)].first_channel = m.num_channels;
    for (int c = 0; c < static_cast<int>(n); ++c)
        m.joints[static_cast<size_t>(index)].channels.push_back(parse_channel(t));
    m.num_channels += static_cast<int>(n);
    while (true) {
        const std::string& w = t.next("JOINT, End Site or '}'");
        if (w == "}") return;
        if (w == "JOINT") {
            const std::string child = t.next("a joint name");
            parse_joint(t, m, child, index, depth + 1);
        } else if (w == "End") {
            t.expect("Site");
            t.expect("{");
            BvhJoint end;
            end.name = name + "/end";
            end.parent = index;
            end.offset = parse_offset(t);
            end.end_site = true;
            t.expect("}");
            m.joints.push_back(end);
        } else {
            --t.i;
            t.fail("JOINT, End Site or '}'");
        }
    }
}

Quat axis_rotation(BvhChannel ch, double degrees) {
    const double a = degrees * M_PI / 180.0;
    const Eigen::Vector3d axis = ch == BvhChannel::x_rotation   ? Eigen::Vector3d::UnitX()
                                 : ch == BvhChannel::y_rotation ? Eigen::Vector3d::UnitY()
                                                                : Eigen::Vector3d::UnitZ();
    return Quat(Eigen::AngleAxisd(a, axis));
}

const char* channel_name(BvhChannel c) {
    switch (c) {
        case BvhChannel::x_position: return "Xposition";
        case BvhChannel::y_position: return "Yposition";
        case BvhChannel::z_position: return "Zposition";
        case BvhChannel::x_rotation: return "Xrotation";
        case BvhChannel::y_rotation: return "Yrotation";
        case BvhChannel::z_rotation: return "Zrotation";
    }
    return "?";
}

}  // namespace

int BvhMotion::find(const std::string& name) const {
    for (size_t j = 0; j < joints.size(); ++j)
        if (joints[j].name == name) return static_cast<int>(j);
    return -1;
}

BvhMotion parse_bvh(const std::string& text, const std::string& source) {
    Tokens t = tokenize(text, source);
    BvhMotion m;
    t.expect("HIERARCHY");
    t.expect("ROOT");
    const std::string root = t.next("a root joint name");
    parse_joint(t, m, root, -1, 0);
    t.expect("MOTION");
    t.expect("Frames:");
    const double frames = t.number("a frame count");
    if (frames < 1 || frames != std::floor(frames) || frames > 1e8) {
        --t.i;
        t.fail("a positive whole frame count");
    }
    t.expect("Frame");
    t.expect("Time:");
    m.frame_time = t.number("a frame time in seconds");
    if (!(m.frame_time > 0)) {
        --t.i;
        t.fail("a positive frame time");
    }
    m.num_frames = static_cast<int>(frames);
    const size_t count = static_cast<size_t>(m.num_frames) * static_cast<size_t>(m.num_channels);
    if (t.words.size() - t.i < count)
        throw Error(source, "MOTION",
                    std::to_string(count) + " values (" + std::to_string(m.num_frames) + " frames x " +
                        std::to_string(m.num_channels) + " channels)",
                    std::to_string(t.words.size() - t.i) + " (truncated)");
    if (t.words.size() - t.i > count)
        throw Error(source, "MOTION",
                    std::to_string(count) + " values (" + std::to_string(m.num_channels) + " channels per frame)",
                    std::to_string(t.words.size() - t.i));
    m.values.resize(count);
    for (size_t k = 0; k < count; ++k) m.values[k] = t.number("a channel value");
    return m;
}

BvhMotion read_bvh(const std::string& path) { return parse_bvh(read_file_text(path), path); }

BvhPose bvh_pose(const BvhMotion& m, int frame, PositionChannels positions) {
    BvhPose p;
    p.rotation.assign(m.joints.size(), Quat::Identity());
    p.translation.resize(m.joints.size());
    const double* v = m.frame(frame);
    for (size_t j = 0; j < m.joints.size(); ++j) {
        const BvhJoint& joint = m.joints[j];
        p.translation[j] = joint.offset;
        bool has_position = false;
        Eigen::Vector3d pos = Eigen::Vector3d::Zero();
        for (size_t c = 0; c < joint.channels.size(); ++c) {
            const double x = v[joint.first_channel + static_cast<int>(c)];
            switch (joint.channels[c]) {
                case BvhChannel::x_position:
                    pos.x() = x;
                    has_position = true;
                    break;
                case BvhChannel::y_position:
                    pos.y() = x;
                    has_position = true;
                    break;
                case BvhChannel::z_position:
                    pos.z() = x;
                    has_position = true;
                    break;
                default: p.rotation[j] = p.rotation[j] * axis_rotation(joint.channels[c], x);
            }
        }
        const bool root_only = positions == PositionChannels::root_only;
        if (!has_position || (root_only && joint.parent >= 0)) continue;
        const bool adds = positions == PositionChannels::add_to_offset || root_only;
        p.translation[j] = adds ? joint.offset + pos : pos;
    }
    return p;
}

std::vector<Eigen::Vector3d> bvh_forward_kinematics(const BvhMotion& m, const BvhPose& p) {
    std::vector<Quat> world_rot(m.joints.size());
    std::vector<Eigen::Vector3d> world_pos(m.joints.size());
    for (size_t j = 0; j < m.joints.size(); ++j) {
        const int parent = m.joints[j].parent;
        if (parent < 0) {
            world_rot[j] = p.rotation[j];
            world_pos[j] = p.translation[j];
        } else {
            const size_t q = static_cast<size_t>(parent);
            world_rot[j] = world_rot[q] * p.rotation[j];
            world_pos[j] = world_pos[q] + world_rot[q] * p.translation[j];
        }
    }
    return world_pos;
}

BvhPose interpolate_pose(const BvhPose& p0, const BvhPose& p1, double a) {
    BvhPose p = p0;
    for (size_t j = 0; j < p.rotation.size(); ++j) {
        p.rotation[j] = slerp(p0.rotation[j], p1.rotation[j], a);
        p.translation[j] = (1 - a) * p0.translation[j] + a * p1.translation[j];
    }
    return p;
}

namespace {

// Writes joint j and its subtree; appends the joints in the order written (depth first).
void format_joint(const BvhMotion& m, const std::vector<std::vector<size_t>>& children, size_t j, size_t depth,
                  std::ostringstream& out, std::vector<size_t>& order) {
    const BvhJoint& joint = m.joints[j];
    const std::string in(2 * depth, ' ');
    if (joint.end_site)
        out << in << "End Site\n";
    else
        out << in << (joint.parent < 0 ? "ROOT " : "JOINT ") << joint.name << "\n";
    out << in << "{\n"
        << in << "  OFFSET " << joint.offset.x() << " " << joint.offset.y() << " " << joint.offset.z() << "\n";
    if (!joint.end_site) {
        out << in << "  CHANNELS " << joint.channels.size();
        for (BvhChannel c : joint.channels) out << " " << channel_name(c);
        out << "\n";
        order.push_back(j);
    }
    for (size_t c : children[j]) format_joint(m, children, c, depth + 1, out, order);
    out << in << "}\n";
}

}  // namespace

std::string format_bvh(const BvhMotion& m) {
    std::ostringstream out;
    out.precision(6);
    out << std::fixed << "HIERARCHY\n";
    std::vector<std::vector<size_t>> children(m.joints.size());
    for (size_t j = 1; j < m.joints.size(); ++j) children[static_cast<size_t>(m.joints[j].parent)].push_back(j);
    std::vector<size_t> order;  // joints with channels, in file order
    format_joint(m, children, 0, 0, out, order);
    out << "MOTION\nFrames: " << m.num_frames << "\nFrame Time: " << std::setprecision(9) << m.frame_time
        << std::setprecision(6) << "\n";
    for (int f = 0; f < m.num_frames; ++f) {
        const double* v = m.frame(f);
        bool first = true;
        for (size_t j : order)
            for (size_t c = 0; c < m.joints[j].channels.size(); ++c) {
                out << (first ? "" : " ") << v[m.joints[j].first_channel + static_cast<int>(c)];
                first = false;
            }
        out << "\n";
    }
    return out.str();
}

}  // namespace t2imu
