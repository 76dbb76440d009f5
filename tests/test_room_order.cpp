// The rooms of src/ (../shared/DESIGN.md, "Layout") look only upstream: a file may include its own room, core,
// and the rooms before it in the pipeline order below, never a room after it, and the torch-free rooms never
// include libtorch or a libtorch room. This test reads every #include of src/ so that the build enforces it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>

namespace fs = std::filesystem;

namespace {

// Pipeline order: text -> motion -> bodies -> sensors -> HAR and analysis -> report; the job and the CLI last.
const std::vector<std::string> kOrder = {"core", "nn",  "motion",   "data",   "text",     "diffusion", "body",
                                         "imu",  "har", "analysis", "report", "pipeline", "cli"};
// Compiled into libt2imu, without libtorch (CMakeLists.txt's T2IMU_ROOMS); a room's nn/ folder (text/nn, har/nn) is
// its libtorch part, built into the libtorch library.
const std::vector<std::string> kTorchFree = {"core", "motion", "data",     "text",  "body",
                                             "imu",  "har",    "analysis", "report"};

int rank_of(const std::string& room) {
    for (size_t i = 0; i < kOrder.size(); ++i)
        if (kOrder[i] == room) return static_cast<int>(i);
    return -1;
}

struct Include {
    std::string file, target;  // relative to src/; the included path
};

std::vector<Include> includes_of_src() {
    std::vector<Include> out;
    const fs::path src = fs::path(T2IMU_SOURCE_DIR) / "src";
    const std::regex line(R"(^\s*#\s*include\s*[<"]([^">]+)[">])");
    for (const auto& e : fs::recursive_directory_iterator(src)) {
        const std::string ext = e.path().extension().string();
        if (ext != ".hpp" && ext != ".cpp") continue;
        std::ifstream in(e.path());
        std::string text;
        std::smatch m;
        while (std::getline(in, text))
            if (std::regex_search(text, m, line)) out.push_back({fs::relative(e.path(), src).generic_string(), m[1]});
    }
    return out;
}

std::string room_of(const std::string& path) { return path.substr(0, path.find('/')); }

}  // namespace

TEST(RoomOrder, EveryRoomIsKnownAndIncludesOnlyUpstream) {
    const std::vector<Include> includes = includes_of_src();
    ASSERT_GT(includes.size(), 500u);
    for (const Include& i : includes) {
        const std::string room = room_of(i.file);
        ASSERT_GE(rank_of(room), 0) << i.file << ": a room DESIGN.md's order does not name";
        if (i.target.find('/') == std::string::npos || rank_of(room_of(i.target)) < 0) continue;  // system headers
        EXPECT_LE(rank_of(room_of(i.target)), rank_of(room))
            << i.file << " includes " << i.target << ", a room downstream of " << room;
    }
}

TEST(RoomOrder, TorchFreeRoomsNeverIncludeLibtorch) {
    for (const Include& i : includes_of_src()) {
        const std::string room = room_of(i.file);
        if (std::find(kTorchFree.begin(), kTorchFree.end(), room) == kTorchFree.end() ||
            i.file.find("/nn/") != std::string::npos)
            continue;
        const bool torch = i.target.rfind("torch/", 0) == 0 || i.target.rfind("ATen/", 0) == 0 ||
                           i.target.rfind("c10/", 0) == 0 || i.target.rfind("nn/", 0) == 0 ||
                           i.target.rfind("diffusion/", 0) == 0 || i.target.rfind("pipeline/", 0) == 0 ||
                           i.target.find("/nn/") != std::string::npos;
        EXPECT_FALSE(torch) << i.file << " includes " << i.target << " but " << room << " is built without libtorch";
    }
}
