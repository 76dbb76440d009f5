// The catch22 reference outputs (shared/data/reference/catch22) read for the per-file tests of the individual
// features (tests/test_catch22_<file>.cpp), plus the z-scoring and the autocorrelation computed here, directly
// from their definitions, so that a feature can be checked on its own against the reference value.
#pragma once
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "test_util.hpp"

namespace t2imu::test {

struct Catch22Reference {
    std::string name;                        // input file name
    std::vector<double> raw;                 // the input as read
    std::vector<double> z;                   // the input, z-scored (sample standard deviation)
    std::vector<double> acf;                 // its autocorrelation, summed directly (not by FFT)
    std::map<std::string, double> expected;  // feature name -> reference value
};

inline std::vector<double> zscore(const std::vector<double>& x) {
    double m = 0.0;
    for (double v : x) m += v;
    m /= static_cast<double>(x.size());
    double ss = 0.0;
    for (double v : x) ss += (v - m) * (v - m);
    const double sd = std::sqrt(ss / static_cast<double>(x.size() - 1));
    std::vector<double> z;
    for (double v : x) z.push_back((v - m) / sd);
    return z;
}

// r(k) = sum_t (x_t - m)(x_{t+k} - m) / sum_t (x_t - m)^2, the O(n^2) sum.
inline std::vector<double> direct_autocorrelation(const std::vector<double>& x) {
    double m = 0.0;
    for (double v : x) m += v;
    m /= static_cast<double>(x.size());
    std::vector<double> r(x.size(), 0.0);
    for (size_t k = 0; k < x.size(); ++k)
        for (size_t t = 0; t + k < x.size(); ++t) r[k] += (x[t] - m) * (x[t + k] - m);
    const double r0 = r[0];
    for (double& v : r) v /= r0;
    return r;
}

// "value, NAME[, seconds]" lines -> name -> value.
inline std::map<std::string, double> read_catch22_reference_output(const std::string& path) {
    std::map<std::string, double> out;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line.find(',') == std::string::npos) continue;
        std::stringstream s(line);
        std::string value, name;
        std::getline(s, value, ',');
        std::getline(s, name, ',');
        name.erase(0, name.find_first_not_of(' '));
        name.erase(name.find_last_not_of(" \r") + 1);
        out[name] = std::strtod(value.c_str(), nullptr);
    }
    return out;
}

// The small reference cases: testData/basic and testData/simulated (n <= 1000; the long sinusoid left out) and
// generated_short_catch24 (its full-precision outputs). Empty when the shared data is absent.
inline std::vector<Catch22Reference> catch22_reference_cases() {
    namespace fs = std::filesystem;
    const std::string list = shared_path("reference/catch22/featureList.txt");
    if (list.empty()) return {};
    const std::string root = fs::path(list).parent_path().string();
    std::vector<std::pair<std::string, std::string>> files;  // input, output
    for (const char* folder : {"testData/basic", "testData/simulated"})
        for (const auto& e : fs::directory_iterator(root + "/" + folder)) {
            const std::string p = e.path().string();
            if (p.size() < 11 || p.compare(p.size() - 11, 11, "_output.txt") != 0) continue;
            if (p.find("testSinusoid") != std::string::npos) continue;  // 5000 samples: slow for the direct sums
            files.push_back({p.substr(0, p.size() - 11) + ".txt", p});
        }
    for (const auto& e : fs::directory_iterator(root + "/generated_short_catch24")) {
        const std::string p = e.path().string();
        if (p.size() < 17 || p.compare(p.size() - 17, 17, "_output24_p17.txt") != 0) continue;
        files.push_back({p.substr(0, p.size() - 17) + ".txt", p});
    }
    std::sort(files.begin(), files.end());
    std::vector<Catch22Reference> cases;
    for (const auto& [input, output] : files) {
        std::ifstream in(input);
        std::vector<double> x;
        for (double v; in >> v;) x.push_back(v);
        Catch22Reference c;
        c.name = fs::path(input).filename().string();
        c.raw = x;
        c.z = zscore(x);
        c.acf = direct_autocorrelation(c.z);
        c.expected = read_catch22_reference_output(output);
        cases.push_back(std::move(c));
    }
    return cases;
}

// The tolerance of test_catch22.cpp: 1e-6 relative, 1e-9 absolute near zero (the outputs print 14 decimals).
inline bool catch22_close(double got, double expected) {
    return std::fabs(got - expected) <= std::max(1e-6 * std::fabs(expected), 1e-9);
}

// Checks one feature, compute(case) -> value, against every reference output that lists it; returns how many.
template <class Compute>
int expect_catch22_feature(const std::vector<Catch22Reference>& cases, const std::string& feature, Compute compute) {
    int checked = 0;
    for (const Catch22Reference& c : cases) {
        const auto it = c.expected.find(feature);
        if (it == c.expected.end()) continue;
        const double got = compute(c);
        EXPECT_TRUE(catch22_close(got, it->second))
            << feature << " of " << c.name << ": " << got << " vs reference " << it->second;
        ++checked;
    }
    return checked;
}

}  // namespace t2imu::test

// Sets `var` to the reference cases, or skips the test when the shared data is missing.
#define CATCH22_REFERENCE_OR_SKIP(var)                                                             \
    do {                                                                                           \
        var = ::t2imu::test::catch22_reference_cases();                                            \
        if (var.empty())                                                                           \
            GTEST_SKIP() << "shared data not found: reference/catch22"                             \
                         << " (expects ../shared/data beside the checkout or $T2IMU_SHARED_DATA)"; \
    } while (0)
