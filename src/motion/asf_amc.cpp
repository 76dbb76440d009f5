#include "motion/asf_amc.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

namespace {

struct AsfBone {
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    double length = 0;
    Quat axis = Quat::Identity();
    std::vector<int> dofs;
};

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> w;
    std::string s;
    while (in >> s) w.push_back(s);
    return w;
}

double number(const std::string& w, const std::string& source, int line, const char* what) {
    return finite_number(w, source, "line " + std::to_string(line), what);
}

// Euler angles (degrees) applied in the order of the letters: "XYZ" gives Rz Ry Rx.
Quat euler_rotation(const double deg[3], const std::string& order, const std::string& source, int line) {
    Quat q = Quat::Identity();
    for (char c : order) {
        const int axis = c == 'X' || c == 'x' ? 0 : c == 'Y' || c == 'y' ? 1 : c == 'Z' || c == 'z' ? 2 : -1;
        if (axis < 0) throw Error(source, "line " + std::to_string(line), "an axis order of X, Y and Z", order);
        q = Quat(Eigen::AngleAxisd(deg[axis] * M_PI / 180.0, Eigen::Vector3d::Unit(axis))) * q;
    }
    return q;
}

int dof_index(const std::string& d) {
    static const char* names[] = {"rx", "ry", "rz", "tx", "ty", "tz"};
    for (int k = 0; k < 6; ++k) {
        std::string lower = d;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (lower == names[k]) return k;
    }
    return -1;
}

std::vector<int> parse_dofs(const std::vector<std::string>& w, size_t from, const std::string& source, int line) {
    std::vector<int> dofs;
    for (size_t k = from; k < w.size(); ++k) {
        const int d = dof_index(w[k]);
        if (d < 0) throw Error(source, "line " + std::to_string(line), "a degree of freedom (rx ry rz tx ty tz)", w[k]);
        dofs.push_back(d);
    }
    return dofs;
}

}  // namespace

AsfSkeleton parse_asf(const std::string& text, const std::string& source) {
    std::istringstream in(text);
    std::string line, section;
    int n = 0;
    double length_unit = 1.0;
    AsfBone root;
    Eigen::Vector3d root_position = Eigen::Vector3d::Zero();
    std::map<std::string, AsfBone> bones;
    std::vector<std::pair<std::string, std::vector<std::string>>> hierarchy;
    std::string current;
    while (std::getline(in, line)) {
        ++n;
        const std::vector<std::string> w = words(line);
        if (w.empty() || w[0][0] == '#') continue;
        if (w[0][0] == ':') {
            section = w[0];
            continue;
        }
        const std::string at = "line " + std::to_string(n);
        if (section == ":units" && w[0] == "length" && w.size() >= 2) {
            length_unit = number(w[1], source, n, "a length unit");
            if (!(length_unit > 0)) throw Error(source, at, "a positive length unit", w[1]);
        } else if (section == ":root") {
            if (w[0] == "order") root.dofs = parse_dofs(w, 1, source, n);
            if (w[0] == "position" && w.size() >= 4)
                root_position = {number(w[1], source, n, "a number"), number(w[2], source, n, "a number"),
                                 number(w[3], source, n, "a number")};
            if (w[0] == "orientation" && w.size() >= 4) {
                const double deg[3] = {number(w[1], source, n, "a number"), number(w[2], source, n, "a number"),
                                       number(w[3], source, n, "a number")};
                root.axis = euler_rotation(deg, "XYZ", source, n);
            }
        } else if (section == ":bonedata") {
            if (w[0] == "begin")
                current.clear();
            else if (w[0] == "name" && w.size() >= 2) {
                current = w[1];
                bones[current];
            } else if (current.empty() && w[0] != "end" && w[0] != "id")
                throw Error(source, at, "a bone name before its data", w[0]);
            else if (w[0] == "direction" && w.size() >= 4)
                bones[current].direction = {number(w[1], source, n, "a number"), number(w[2], source, n, "a number"),
                                            number(w[3], source, n, "a number")};
            else if (w[0] == "length" && w.size() >= 2)
                bones[current].length = number(w[1], source, n, "a bone length");
            else if (w[0] == "axis" && w.size() >= 5) {
                const double deg[3] = {number(w[1], source, n, "a number"), number(w[2], source, n, "a number"),
                                       number(w[3], source, n, "a number")};
                bones[current].axis = euler_rotation(deg, w[4], source, n);
            } else if (w[0] == "dof")
                bones[current].dofs = parse_dofs(w, 1, source, n);
        } else if (section == ":hierarchy" && w[0] != "begin" && w[0] != "end") {
            hierarchy.push_back({w[0], std::vector<std::string>(w.begin() + 1, w.end())});
        }
    }
    if (bones.empty() || hierarchy.empty()) throw Error(source, "ASF", ":bonedata and :hierarchy sections");

    AsfSkeleton s;
    s.metres_per_unit = 0.0254 / length_unit;
    BvhJoint r;
    r.name = "root";
    r.offset = root_position;
    s.structure.joints.push_back(r);
    s.axis.push_back(root.axis);
    s.dofs.push_back(root.dofs);
    // Breadth-first over the hierarchy keeps parents before children.
    std::vector<std::string> queue = {"root"};
    for (size_t qi = 0; qi < queue.size(); ++qi) {
        const std::string parent = queue[qi];
        const int parent_index = s.structure.find(parent);
        const Eigen::Vector3d parent_bone = parent == "root"
                                                ? Eigen::Vector3d::Zero()
                                                : Eigen::Vector3d(bones[parent].direction * bones[parent].length);
        bool has_children = false;
        for (const auto& [p, children] : hierarchy) {
            if (p != parent) continue;
            for (const std::string& child : children) {
                if (!bones.count(child)) throw Error(source, ":hierarchy", "bones defined in :bonedata", child);
                if (s.structure.find(child) >= 0) throw Error(source, ":hierarchy", "each bone once", child);
                BvhJoint j;
                j.name = child;
                j.parent = parent_index;
                j.offset = parent_bone;
                s.structure.joints.push_back(j);
                s.axis.push_back(bones[child].axis);
                s.dofs.push_back(bones[child].dofs);
                queue.push_back(child);
                has_children = true;
            }
        }
        if (!has_children && parent != "root") {
            BvhJoint end;
            end.name = parent + "/end";
            end.parent = parent_index;
            end.offset = parent_bone;
            end.end_site = true;
            s.structure.joints.push_back(end);
            s.axis.push_back(Quat::Identity());
            s.dofs.emplace_back();
        }
    }
    return s;
}

AsfSkeleton read_asf(const std::string& path) { return parse_asf(read_file_text(path), path); }

std::vector<BvhPose> parse_amc(const std::string& text, const AsfSkeleton& s, const std::string& source) {
    std::istringstream in(text);
    std::string line;
    int n = 0;
    std::vector<BvhPose> poses;
    const size_t joints = s.structure.joints.size();
    auto new_pose = [&] {
        BvhPose p;
        p.rotation.assign(joints, Quat::Identity());
        p.translation.resize(joints);
        for (size_t j = 0; j < joints; ++j) p.translation[j] = s.structure.joints[j].offset;
        return p;
    };
    while (std::getline(in, line)) {
        ++n;
        const std::vector<std::string> w = words(line);
        if (w.empty() || w[0][0] == '#' || w[0][0] == ':') continue;
        const std::string at = "line " + std::to_string(n);
        if (w.size() == 1 && std::isdigit(static_cast<unsigned char>(w[0][0]))) {
            poses.push_back(new_pose());
            continue;
        }
        if (poses.empty()) throw Error(source, at, "a frame number before the first bone line", w[0]);
        const int j = s.structure.find(w[0]);
        if (j < 0 || s.structure.joints[static_cast<size_t>(j)].end_site)
            throw Error(source, at, "a bone of the ASF skeleton", w[0]);
        const std::vector<int>& dofs = s.dofs[static_cast<size_t>(j)];
        if (w.size() - 1 != dofs.size())
            throw Error(source, at, std::to_string(dofs.size()) + " values for " + w[0], std::to_string(w.size() - 1));
        double rot[3] = {0, 0, 0};
        Eigen::Vector3d trans = Eigen::Vector3d::Zero();
        bool translated = false;
        for (size_t k = 0; k < dofs.size(); ++k) {
            const double v = number(w[k + 1], source, n, "a number");
            if (dofs[k] < 3)
                rot[dofs[k]] = v;
            else {
                trans[dofs[k] - 3] = v;
                translated = true;
            }
        }
        const Quat& c = s.axis[static_cast<size_t>(j)];
        BvhPose& pose = poses.back();
        pose.rotation[static_cast<size_t>(j)] = c * euler_rotation(rot, "XYZ", source, n) * c.conjugate();
        if (translated)
            pose.translation[static_cast<size_t>(j)] = s.structure.joints[static_cast<size_t>(j)].offset + trans;
    }
    if (poses.empty()) throw Error(source, "AMC", "at least one frame");
    return poses;
}

std::vector<BvhPose> read_amc(const std::string& path, const AsfSkeleton& skeleton) {
    return parse_amc(read_file_text(path), skeleton, path);
}

}  // namespace t2imu
