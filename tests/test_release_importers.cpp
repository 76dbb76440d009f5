// Damaged release files: a line of garbage or nan, a huge sensor id or part number, a nan cell, a folder where
// nothing is usable. Each is refused naming the file and the line or field; an import where every file is
// refused is refused as a whole, naming the first reason.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/zip_archive.hpp"
#include "har/datasets/hugadb.hpp"
#include "har/datasets/realworld.hpp"
#include "har/datasets/release_files.hpp"
#include "har/datasets/sisfall.hpp"
#include "har/datasets/umafall.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

// A SisFall walking trial of 40 samples at 200 Hz; `bad` (when given) replaces line `at`.
void write_sisfall(const std::string& path, int at = -1, const std::string& bad = "") {
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream out(path);
    for (int i = 1; i <= 40; ++i) out << (i == at ? bad : "17, -254, -19, 41, 5, -1, 63, -1000, -77") << ";\n";
}

const std::string kUmafallHeader =
    "% Universidad de Malaga - ETSI de Telecomunicacion (Spain)\n"
    "% Sensor_ID; Position; Device Model\n";

}  // namespace

TEST(ReleaseImporters, SisFallRefusesAGarbageOrNanLineInsteadOfDroppingIt) {
    const std::string dir = test::scratch_dir("release_sisfall");
    write_sisfall(dir + "/SA01/D01_SA01_R01.txt");
    write_sisfall(dir + "/SA01/D01_SA01_R02.txt", 7, "nan, -254, -19, 41, 5, -1, 63, -1000, -77");
    write_sisfall(dir + "/SA01/D01_SA01_R03.txt", 9, "\x01\x02garbage 1 2 3");
    std::vector<std::string> skipped;
    EXPECT_EQ(import_sisfall(dir, &skipped).size(), 1u);
    ASSERT_EQ(skipped.size(), 2u);
    EXPECT_NE(skipped[0].find("D01_SA01_R02.txt: line 7: expected 9 raw values"), std::string::npos) << skipped[0];
    EXPECT_NE(skipped[0].find("'nan'"), std::string::npos) << skipped[0];
    EXPECT_NE(skipped[1].find("D01_SA01_R03.txt: line 9"), std::string::npos) << skipped[1];
    // Nothing usable: the import itself is refused, with the first file's reason.
    fs::remove(dir + "/SA01/D01_SA01_R01.txt");
    skipped.clear();
    const std::string m = test::error_message([&] { import_sisfall(dir, &skipped); });
    EXPECT_NE(m.find(dir + ": recordings: expected at least one usable recording among 2"), std::string::npos) << m;
    EXPECT_NE(m.find("first refusal: " + dir + "/SA01/D01_SA01_R02.txt"), std::string::npos) << m;
}

TEST(ReleaseImporters, UmafallRefusesAHugeSensorIdByNameNotByStoi) {
    const std::string dir = test::scratch_dir("release_umafall");
    const std::string file = dir + "/UMAFall_Subject_01_ADL_Walking_1_2017-04-14_23-38-23.csv";
    std::ofstream(file) << kUmafallHeader << "% C4:BE:84:70:64:8A; 99999999999999; WAIST; SensorTag\n"
                        << "% TimeStamp; Sample No; X-Axis; Y-Axis; Z-Axis; Sensor Type; Sensor ID\n";
    std::vector<std::string> skipped;
    EXPECT_THROW(import_umafall(dir, &skipped), Error);
    ASSERT_EQ(skipped.size(), 1u);
    EXPECT_NE(skipped[0].find("line 3 sensor id: expected a whole number from 0 to 999999 (got '99999999999999')"),
              std::string::npos)
        << skipped[0];
    EXPECT_EQ(skipped[0].find("stoi"), std::string::npos);
    // A sample counter of 1.5e21 (found by fuzz_umafall: its cast to long was undefined behaviour).
    std::ofstream(file) << kUmafallHeader << "% C4:BE:84:70:64:8A; 3; WAIST; SensorTag\n"
                        << "1000;1.5e21;0.1;0.2;0.9;0;3\n";
    skipped.clear();
    EXPECT_THROW(import_umafall(dir, &skipped), Error);
    ASSERT_EQ(skipped.size(), 1u);
    EXPECT_NE(skipped[0].find("line 4 sample no: expected a whole number from 0 to 10^12 (got '1.5e21')"),
              std::string::npos)
        << skipped[0];
    EXPECT_EQ(test::error_message([] { release_index("-3", "f", "id"); }),
              "f: id: expected a whole number from 0 to 999999 (got '-3')");
    EXPECT_EQ(release_index("000042", "f", "id"), 42);
}

TEST(ReleaseImporters, RealWorldRefusesANanCellAndAHugePartNumber) {
    const std::string dir = test::scratch_dir("release_realworld");
    fs::create_directories(dir + "/proband1/data");
    const auto csv = [](const std::string& cell) {
        std::string s = "id,attr_time,attr_x,attr_y,attr_z\n";
        for (int i = 0; i < 60; ++i)
            s += std::to_string(i + 1) + "," + std::to_string(1000 + 20 * i) + "," + (i == 5 ? cell : "0.1") +
                 ",9.8,0\n";
        return std::vector<uint8_t>(s.begin(), s.end());
    };
    write_zip(dir + "/proband1/data/acc_walking_csv.zip", {{"acc_walking_chest.csv", csv("nan")}});
    write_zip(dir + "/proband1/data/gyr_walking_csv.zip", {{"Gyroscope_walking_chest.csv", csv("0.2")}});
    std::vector<std::string> skipped;
    const std::string m = test::error_message([&] { import_realworld(dir, &skipped); });
    EXPECT_NE((m + (skipped.empty() ? "" : skipped[0]))
                  .find("acc_walking_chest.csv: row 7 column 'attr_x': expected a finite number (got nan)"),
              std::string::npos)
        << m << " / " << (skipped.empty() ? "" : skipped[0]);
    fs::remove_all(dir + "/proband1/data");
    fs::create_directories(dir + "/proband1/data");
    write_zip(dir + "/proband1/data/acc_walking_csv.zip", {{"acc_walking_99999999999_chest.csv", csv("0.1")}});
    skipped.clear();
    const std::string huge = test::error_message([&] { import_realworld(dir, &skipped); });
    EXPECT_NE(
        (huge + (skipped.empty() ? "" : skipped[0])).find("part number: expected a whole number from 0 to 999999"),
        std::string::npos)
        << huge;
}

TEST(ReleaseImporters, HugadbRefusesAnActivityIdOutOfRangeBeforeCastingIt) {
    // 38 numbers and an activity id of -1.9e10 (found by fuzz_hugadb: its cast to int was undefined behaviour).
    const std::string path = test::scratch_dir("release_hugadb") + "/HuGaDB_v1_walking_01_00.txt";
    std::string row;
    for (int i = 0; i < 38; ++i) row += "1\t";
    std::ofstream(path) << row << "-18966700000\n";
    const std::string m = test::error_message([&] { read_hugadb_file(path); });
    EXPECT_NE(m.find("line 1: expected an activity id from 1 to 12"), std::string::npos) << m;
}
