// import_release_files: every matching file under the folder (recursively) in sorted order, others ignored; a
// file the reader refuses is skipped with its message kept (or the error passed on when no list is given); a
// folder with no matching file is refused naming the folder and what was expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "har/datasets/release_files.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {
std::string make_release(const std::string& name) {
    const std::string dir = test::scratch_dir(name);
    fs::create_directories(dir + "/SA02");
    fs::create_directories(dir + "/SA01");
    for (const char* f : {"SA02/D01_SA02_R01.txt", "SA01/D02_SA01_R01.txt", "SA01/D01_SA01_R01.txt", "README.txt",
                          "SA01/D01_SA01_R01.txt.bak", "SA01/BAD_SA01_R01.txt"})
        std::ofstream(dir + "/" + f) << f;
    return dir;
}

// One recording per file, named by the file; files whose name starts with BAD are refused.
std::vector<ImuRecording> fake_reader(const std::string& path) {
    const std::string name = fs::path(path).filename().string();
    if (name.rfind("BAD", 0) == 0) throw Error(path, "header", "a SisFall trial", "garbage");
    ImuRecording r;
    r.path = name;
    r.subject = fs::path(path).parent_path().filename().string();
    return {r};
}
}  // namespace

TEST(ReleaseFiles, ReadsMatchingFilesInSortedOrderAndSkipsRefusedOnes) {
    const std::string dir = make_release("release_files_ok");
    std::vector<std::string> skipped;
    const std::vector<ImuRecording> r =
        import_release_files(dir, std::regex(R"([A-Z]+\d*_SA\d+_R\d+\.txt)"), "SisFall trials", fake_reader, &skipped);
    // Sorted by full path: SA01/D01, SA01/D02, SA02/D01; README.txt and the .bak copy do not match.
    ASSERT_EQ(r.size(), 3u);
    EXPECT_EQ(r[0].path, "D01_SA01_R01.txt");
    EXPECT_EQ(r[1].path, "D02_SA01_R01.txt");
    EXPECT_EQ(r[2].path, "D01_SA02_R01.txt");
    EXPECT_EQ(r[2].subject, "SA02");
    ASSERT_EQ(skipped.size(), 1u);
    EXPECT_NE(skipped[0].find("BAD_SA01_R01.txt"), std::string::npos) << skipped[0];
    EXPECT_NE(skipped[0].find("header"), std::string::npos) << skipped[0];
}

TEST(ReleaseFiles, WithoutASkipListARefusedFileStopsTheImport) {
    const std::string dir = make_release("release_files_strict");
    try {
        import_release_files(dir, std::regex(R"(.*_R\d+\.txt)"), "SisFall trials", fake_reader, nullptr);
        ADD_FAILURE() << "a refused file was skipped silently";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("BAD_SA01_R01.txt"), std::string::npos) << e.what();
    }
}

TEST(ReleaseFiles, AFolderWithoutMatchingFilesIsRefused) {
    const std::string dir = make_release("release_files_none");
    std::vector<std::string> skipped;
    try {
        import_release_files(dir, std::regex(R"(.*\.csv)"), "UMAFall .csv recordings", fake_reader, &skipped);
        ADD_FAILURE() << "an empty import accepted";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(dir), std::string::npos) << m;
        EXPECT_NE(m.find("files"), std::string::npos) << m;
        EXPECT_NE(m.find("UMAFall .csv recordings"), std::string::npos) << m;
    }
}
