// Output paths checked before work: missing folders are proven creatable and removed again, a file in the way
// and an empty path are refused naming the option; make_directories; the partial-folder name; stale partial
// folders of dead processes removed, a live process's kept.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.hpp"
#include "core/output_path.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {
}  // namespace

TEST(OutputPath, MissingFoldersAreProvenAndLeftUnmade) {
    const std::string dir = test::scratch_dir("output_path_missing");
    EXPECT_NO_THROW(check_output_path(dir + "/a/b/c/out.csv", "--out"));
    EXPECT_FALSE(fs::exists(dir + "/a"));  // nothing left behind
    EXPECT_NO_THROW(check_output_path(dir + "/existing.csv", "--out"));
    EXPECT_NO_THROW(check_output_path(dir + "/run/", "--out"));  // a folder to be made, with a trailing slash
    EXPECT_FALSE(fs::exists(dir + "/run"));
}

TEST(OutputPath, AFileInTheWayAndAnEmptyPathAreRefused) {
    const std::string dir = test::scratch_dir("output_path_file");
    std::ofstream(dir + "/file.txt") << "x";
    std::string m = test::error_message([&] { check_output_path(dir + "/file.txt/sub/out.csv", "--report"); });
    EXPECT_TRUE(test::contains(m, "--report") && test::contains(m, dir + "/file.txt") && test::contains(m, "is a file")) << m;
    m = test::error_message([&] { check_output_path("", "--out"); });
    EXPECT_TRUE(test::contains(m, "--out") && test::contains(m, "an output path")) << m;
    m = test::error_message([&] { make_directories(dir + "/file.txt/sub", "output folder"); });
    EXPECT_TRUE(test::contains(m, dir + "/file.txt/sub") && test::contains(m, "output folder")) << m;
    EXPECT_EQ(fs::file_size(dir + "/file.txt"), 1u);  // untouched
}

TEST(OutputPath, MakeDirectoriesCreatesNestedFolders) {
    const std::string dir = test::scratch_dir("output_path_make");
    make_directories(dir + "/x/y/z", "jobs");
    EXPECT_TRUE(fs::is_directory(dir + "/x/y/z"));
    EXPECT_NO_THROW(make_directories(dir + "/x/y/z", "jobs"));  // existing is fine
}

TEST(OutputPath, PartialPathIsAbsoluteWithThisProcessId) {
    const std::string dir = test::scratch_dir("output_path_partial");
    const std::string suffix = ".partial-" + std::to_string(::getpid());
    EXPECT_EQ(partial_path_for(dir + "/out"), dir + "/out" + suffix);
    EXPECT_EQ(partial_path_for(dir + "/./sub/../out/"), dir + "/out" + suffix);  // normalised, no trailing slash
    const fs::path cwd = fs::current_path();
    fs::current_path(dir);
    EXPECT_EQ(partial_path_for("rel"), (fs::path(dir) / "rel").string() + suffix);
    fs::current_path(cwd);
}

TEST(OutputPath, RemovesOnlyStalePartialsOfThisPath) {
    const std::string dir = test::scratch_dir("output_path_stale");
    // A process id that is surely gone: a child that has exited and been reaped.
    const pid_t child = fork();
    if (child == 0) _exit(0);
    ASSERT_GT(child, 0);
    waitpid(child, nullptr, 0);
    const std::string dead = dir + "/out.partial-" + std::to_string(child);
    const std::string live = dir + "/out.partial-" + std::to_string(::getpid());
    const std::string other = dir + "/other.partial-" + std::to_string(child);
    const std::string odd = dir + "/out.partial-abc";
    for (const std::string& p : {dead, live, other, odd}) {
        fs::create_directories(p + "/inner");
        std::ofstream(p + "/inner/f.txt") << "x";
    }
    remove_stale_partials(dir + "/out");
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_TRUE(fs::exists(live));   // a live process (this one)
    EXPECT_TRUE(fs::exists(other));  // another output's partial
    EXPECT_TRUE(fs::exists(odd));    // not a process id
}

TEST(OutputPath, PublishReplacesAFolderWhole) {
    const std::string dir = test::scratch_dir("output_path_publish");
    const std::string out = dir + "/result", partial = partial_path_for(out);
    fs::create_directories(out);
    std::ofstream(out + "/old.csv") << "old\n";
    std::ofstream(out + "/" + kOutputMarker) << "\n";  // an output t2imu published before
    fs::create_directories(partial);
    std::ofstream(partial + "/new.csv") << "new\n";
    publish_partial(partial, out);
    EXPECT_TRUE(fs::exists(out + "/new.csv"));
    EXPECT_TRUE(fs::exists(out + "/" + kOutputMarker));
    EXPECT_FALSE(fs::exists(out + "/old.csv"));  // replaced whole, not merged
    EXPECT_FALSE(fs::exists(partial));
    size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1u);  // the old output moved aside was removed
    // Nothing to publish: an Error names the output, which keeps what it held.
    EXPECT_TRUE(test::contains(test::error_message([&] { publish_partial(partial, out); }), out + ": rename"));
    EXPECT_TRUE(fs::exists(out + "/new.csv"));
}

TEST(OutputPath, NeverReplacesAUsersFileOrFolder) {
    const std::string dir = test::scratch_dir("output_path_users");
    const std::string file = dir + "/notes.txt", folder = dir + "/mine";
    std::ofstream(file) << "mine\n";
    fs::create_directories(folder);
    std::ofstream(folder + "/a.txt") << "mine\n";
    EXPECT_TRUE(test::contains(test::error_message([&] { check_output_folder(file, "--out"); }), "--out: " + file));
    EXPECT_TRUE(test::contains(test::error_message([&] { check_replaceable_folder(folder, "--out"); }), "did not make"));
    EXPECT_NO_THROW(check_output_folder(folder, "--out"));  // resumable jobs write into a folder
    for (const std::string& target : {file, folder}) {
        const std::string partial = partial_path_for(target);
        fs::create_directories(partial);
        EXPECT_TRUE(test::contains(test::error_message([&] { publish_partial(partial, target); }), target));
        fs::remove_all(partial);
    }
    std::ifstream in(file);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "mine\n");
    EXPECT_TRUE(fs::exists(folder + "/a.txt"));
    // An empty folder may be filled.
    fs::create_directories(dir + "/empty");
    EXPECT_NO_THROW(check_replaceable_folder(dir + "/empty", "--out"));
}

TEST(OutputPath, PathsFromInputsStayInsideTheirFolder) {
    const std::string dir = test::scratch_dir("output_path_confined");
    EXPECT_EQ(confined_path(dir, "a/b.csv", "path"), dir + "/a/b.csv");
    EXPECT_EQ(confined_path(dir, "a/../b.csv", "path"), dir + "/b.csv");
    for (const char* bad : {"../x.csv", "a/../../x.csv", "/etc/passwd", "", "."})
        EXPECT_TRUE(test::contains(test::error_message([&] { confined_path(dir, bad, "manifest.csv row 2"); }), "manifest.csv row 2")) << bad;
    fs::create_directories(dir + "/real");
    fs::create_symlink("/tmp", dir + "/link");
    EXPECT_TRUE(test::contains(test::error_message([&] { confined_path(dir, "link/x.csv", "path"); }), "symbolic link"));
}
