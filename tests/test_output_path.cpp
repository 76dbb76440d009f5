// The output-path guard (check_output): missing folders are proven creatable and removed again; a file in the
// way, an empty path, a symbolic link, a "LINK/.." path resolved as the system resolves it, a folder t2imu did not
// make, a folder where a file goes, an input as the output and a place that refuses new entries (/proc) are
// refused naming the option, with nothing changed on disk; make_directories; the partial-folder name; stale
// partial folders of dead processes removed, a live process's kept; publishing resolves the path first.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include "core/error.hpp"
#include "core/output_path.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

// Every path below `root` with its kind and bytes: equal before and after a refused check means nothing changed.
std::string tree_listing(const std::string& root) {
    std::string listing;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        listing += it->path().string();
        if (it->is_symlink())
            listing += " -> " + fs::read_symlink(it->path()).string();
        else if (it->is_regular_file()) {
            std::ifstream in(it->path(), std::ios::binary);
            listing += " = " + std::string(std::istreambuf_iterator<char>(in), {});
        }
        listing += "\n";
    }
    return listing;
}

void expect_refused(const std::function<void()>& check, const std::string& root, const std::string& why) {
    const std::string before = tree_listing(root);
    const std::string m = test::error_message(check);
    EXPECT_TRUE(test::contains(m, "--out") && test::contains(m, why)) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_EQ(tree_listing(root), before) << why;
}

}  // namespace

TEST(OutputPath, MissingFoldersAreProvenAndLeftUnmade) {
    const std::string dir = test::scratch_dir("output_path_missing");
    EXPECT_NO_THROW(check_output(dir + "/a/b/c/out.csv", "--out", OutputKind::file));
    EXPECT_FALSE(fs::exists(dir + "/a"));  // nothing left behind
    EXPECT_NO_THROW(check_output(dir + "/existing.csv", "--out", OutputKind::file));
    EXPECT_NO_THROW(
        check_output(dir + "/run/", "--out", OutputKind::folder));  // a folder to be made, with a trailing slash
    EXPECT_FALSE(fs::exists(dir + "/run"));
}

TEST(OutputPath, AFileInTheWayAndAnEmptyPathAreRefused) {
    const std::string dir = test::scratch_dir("output_path_file");
    std::ofstream(dir + "/file.txt") << "x";
    std::string m =
        test::error_message([&] { check_output(dir + "/file.txt/sub/out.csv", "--report", OutputKind::file); });
    EXPECT_TRUE(test::contains(m, "--report") && test::contains(m, dir + "/file.txt") && test::contains(m, "is a file"))
        << m;
    m = test::error_message([&] { check_output("", "--out", OutputKind::file); });
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
    EXPECT_TRUE(test::contains(test::error_message([&] { check_output(file, "--out", OutputKind::folder); }),
                               "--out: " + file));
    EXPECT_TRUE(test::contains(test::error_message([&] { check_output(folder, "--out", OutputKind::folder); }),
                               "did not make"));
    std::ofstream(folder + "/" + kOutputMarker) << "\n";
    EXPECT_NO_THROW(check_output(folder, "--out", OutputKind::folder));  // a folder t2imu made: written into again
    fs::remove(folder + "/" + kOutputMarker);
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
    EXPECT_NO_THROW(check_output(dir + "/empty", "--out", OutputKind::folder));
}

TEST(OutputPath, PathsFromInputsStayInsideTheirFolder) {
    const std::string dir = test::scratch_dir("output_path_confined");
    EXPECT_EQ(confined_path(dir, "a/b.csv", "path"), dir + "/a/b.csv");
    EXPECT_EQ(confined_path(dir, "a/../b.csv", "path"), dir + "/b.csv");
    for (const char* bad : {"../x.csv", "a/../../x.csv", "/etc/passwd", "", "."})
        EXPECT_TRUE(test::contains(test::error_message([&] { confined_path(dir, bad, "manifest.csv row 2"); }),
                                   "manifest.csv row 2"))
            << bad;
    fs::create_directories(dir + "/real");
    fs::create_symlink("/tmp", dir + "/link");
    EXPECT_TRUE(
        test::contains(test::error_message([&] { confined_path(dir, "link/x.csv", "path"); }), "symbolic link"));
}

TEST(OutputPath, ASymbolicLinkAsOutIsRefusedWhereverItPoints) {
    const std::string dir = test::scratch_dir("output_path_symlink");
    fs::create_directories(dir + "/target");
    std::ofstream(dir + "/target/" + kOutputMarker) << "\n";  // even a folder t2imu made, reached through a link
    fs::create_symlink(dir + "/target", dir + "/link");
    fs::create_symlink(dir + "/nowhere", dir + "/dangling");
    for (const OutputKind kind : {OutputKind::file, OutputKind::folder}) {
        expect_refused([&] { check_output(dir + "/link", "--out", kind); }, dir, "symbolic link");
        expect_refused([&] { check_output(dir + "/link/", "--out", kind); }, dir, "symbolic link");
        expect_refused([&] { check_output(dir + "/dangling", "--out", kind); }, dir, "symbolic link");
    }
    EXPECT_NO_THROW(check_output(dir + "/link/inner", "--out",
                                 OutputKind::folder));  // a link above the output is the system's business
}

TEST(OutputPath, LinkDotDotIsResolvedAsTheSystemResolvesIt) {
    // ot/lnkdir -> elsewhere/deep, so ot/lnkdir/../victim is elsewhere/victim for the kernel (lexically: ot/victim).
    const std::string dir = test::scratch_dir("output_path_dotdot");
    fs::create_directories(dir + "/ot");
    fs::create_directories(dir + "/elsewhere/deep");
    fs::create_directories(dir + "/elsewhere/victim");
    std::ofstream(dir + "/elsewhere/victim/thesis.txt") << "six years\n";
    fs::create_symlink(dir + "/elsewhere/deep", dir + "/ot/lnkdir");
    const std::string path = dir + "/ot/lnkdir/../victim";
    EXPECT_EQ(resolved_output_path(path), dir + "/elsewhere/victim");
    EXPECT_EQ(resolved_output_path(dir + "/ot/lnkdir/../new/x.csv"), dir + "/elsewhere/new/x.csv");
    expect_refused([&] { check_output(path, "--out", OutputKind::folder); }, dir, "did not make");
    expect_refused([&] { check_output(path, "--out", OutputKind::file); }, dir, "an existing folder");
    // The rename step resolves too: a partial published onto "LINK/../victim" is judged as the real victim.
    const std::string partial = partial_path_for(path);
    EXPECT_EQ(partial, dir + "/elsewhere/victim.partial-" + std::to_string(::getpid()));
    fs::create_directories(partial);
    EXPECT_TRUE(test::contains(test::error_message([&] { publish_partial(partial, path); }), "did not make"));
    EXPECT_TRUE(fs::exists(dir + "/elsewhere/victim/thesis.txt"));
    // A folder t2imu made, reached the same way, is replaced where it really is.
    std::ofstream(dir + "/elsewhere/victim/" + kOutputMarker) << "\n";
    std::ofstream(partial + "/new.csv") << "new\n";
    publish_partial(partial, path);
    EXPECT_TRUE(fs::exists(dir + "/elsewhere/victim/new.csv"));
    EXPECT_FALSE(fs::exists(dir + "/ot/victim"));
}

TEST(OutputPath, AFolderWhereAFileGoesAndAForeignFolderAreRefused) {
    const std::string dir = test::scratch_dir("output_path_kinds");
    fs::create_directories(dir + "/empty");
    fs::create_directories(dir + "/made");
    std::ofstream(dir + "/made/" + kOutputMarker) << "\n";
    fs::create_directories(dir + "/users");
    std::ofstream(dir + "/users/manifest.csv") << "mine\n";
    for (const char* folder : {"/empty", "/made", "/users"})
        expect_refused([&] { check_output(dir + folder, "--out", OutputKind::file); }, dir, "an existing folder");
    expect_refused([&] { check_output(dir + "/users", "--out", OutputKind::folder); }, dir, "did not make");
    expect_refused([&] { check_output(dir + "/users/", "--out", OutputKind::folder); }, dir, "did not make");
    expect_refused([&] { check_output("/dev/null", "--out", OutputKind::file); }, dir, "special file");
    EXPECT_NO_THROW(check_output(dir + "/empty", "--out", OutputKind::folder));
    EXPECT_NO_THROW(check_output(dir + "/made", "--out", OutputKind::folder));
    EXPECT_NO_THROW(
        check_output(dir + "/users/manifest.csv", "--out", OutputKind::file));  // a file is replaced by a file
}

TEST(OutputPath, AnInputAsOutputIsRefused) {
    const std::string dir = test::scratch_dir("output_path_inputs");
    fs::create_directories(dir + "/set/recordings");
    std::ofstream(dir + "/set/" + kOutputMarker) << "\n";
    std::ofstream(dir + "/set/manifest.csv") << "m\n";
    std::ofstream(dir + "/series.txt") << "1 2 3\n";
    fs::create_symlink(dir + "/series.txt", dir + "/series-link.txt");
    expect_refused([&] { check_output(dir + "/series.txt", "--out", OutputKind::file, {dir + "/series.txt"}); }, dir,
                   "it is the input");
    expect_refused([&] { check_output(dir + "/./series.txt", "--out", OutputKind::file, {dir + "/series-link.txt"}); },
                   dir, "it is the input");
    expect_refused([&] { check_output(dir + "/set", "--out", OutputKind::folder, {dir + "/set"}); }, dir,
                   "it is the input");
    expect_refused([&] { check_output(dir + "/set/", "--out", OutputKind::folder, {dir + "/set/manifest.csv"}); }, dir,
                   "it holds the input");
    EXPECT_NO_THROW(
        check_output(dir + "/set/report", "--out", OutputKind::folder, {dir + "/set"}));  // below an input is fine
    EXPECT_NO_THROW(check_output(dir + "/out.csv", "--out", OutputKind::file,
                                 {"", dir + "/series.txt"}));  // "": an option not given
}

TEST(OutputPath, APlaceThatRefusesNewEntriesFailsTheCheck) {
    // /proc says yes to access() for root and refuses mkdir: only the probe entry shows it.
    if (!fs::is_directory("/proc/self")) GTEST_SKIP() << "no /proc";
    for (const char* path : {"/proc/t2imu-out", "/proc/t2imu-x/out.csv", "/proc/self/t2imu-out"}) {
        const std::string m = test::error_message([&] { check_output(path, "--out", OutputKind::folder); });
        EXPECT_TRUE(test::contains(m, "--out: ") && test::contains(m, path)) << m;
    }
    EXPECT_FALSE(fs::exists("/proc/t2imu-x"));
    const std::string dir = test::scratch_dir("output_path_probe");
    check_output(dir + "/a/b/out", "--out", OutputKind::folder);
    size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 0u);  // the probe and the folders made to prove the path are gone
}

TEST(OutputPath, AClaimedFolderIsMadeAndMarked) {
    const std::string dir = test::scratch_dir("output_path_claim");
    claim_output_folder(dir + "/run/a");
    EXPECT_TRUE(fs::exists(dir + "/run/a/" + kOutputMarker));
    std::ofstream(dir + "/run/a/manifest.csv") << "m\n";
    EXPECT_NO_THROW(check_output(dir + "/run/a", "--out", OutputKind::folder));  // a rerun resumes in it
}
