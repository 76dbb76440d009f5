// t2imu tsne: a feature table -> a 2-D t-SNE embedding (and its trustworthiness).
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "analysis/tsne.hpp"
#include "cli/command.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"

namespace t2imu::cli {

namespace {

bool is_number(const std::string& s) {
    if (s.empty()) return false;
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size();
}

struct TsneArgs {
    std::string in, out;
    TsneOptions options;
};

// Numeric columns are the features; the others (labels, paths) are copied to the output beside tsne_x, tsne_y.
void run(const TsneArgs& a) {
    const CsvTable table = read_csv(a.in);
    if (table.rows.empty()) throw Error(a.in, "rows", "at least one data row");
    std::vector<size_t> features, passthrough;
    for (size_t c = 0; c < table.header.size(); ++c) {
        bool numeric = true;
        for (const auto& row : table.rows) numeric = numeric && (is_number(row[c]) || row[c] == "nan" || row[c] == "NaN");
        (numeric ? features : passthrough).push_back(c);
    }
    if (features.empty()) throw Error(a.in, "columns", "numeric feature columns");
    PointMatrix x(static_cast<Eigen::Index>(table.rows.size()), static_cast<Eigen::Index>(features.size()));
    for (size_t r = 0; r < table.rows.size(); ++r)
        for (size_t f = 0; f < features.size(); ++f) x(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(f)) = table.number(r, features[f]);
    // Features on very different scales (catch22 mixes counts and fractions) are standardised first.
    for (Eigen::Index c = 0; c < x.cols(); ++c) {
        const double mean = x.col(c).mean();
        const double sd = std::sqrt((x.col(c).array() - mean).square().mean());
        x.col(c) = sd > 0 ? Eigen::VectorXd((x.col(c).array() - mean) / sd) : Eigen::VectorXd::Zero(x.rows());
    }
    const TsneResult result = tsne(x, a.options);
    CsvTable out;
    for (size_t c : passthrough) out.header.push_back(table.header[c]);
    out.header.push_back("tsne_x");
    out.header.push_back("tsne_y");
    char buf[64];
    for (size_t r = 0; r < table.rows.size(); ++r) {
        std::vector<std::string> row;
        for (size_t c : passthrough) row.push_back(table.rows[r][c]);
        for (int d = 0; d < 2; ++d) {
            std::snprintf(buf, sizeof buf, "%.6g", result.embedding(static_cast<Eigen::Index>(r), d));
            row.push_back(buf);
        }
        out.rows.push_back(row);
    }
    write_csv(a.out, out);
    const int k = std::min<int>(5, static_cast<int>((2 * x.rows() - 2) / 3));
    std::printf("%s: %lld points, %zu features, KL %.4f, trustworthiness (k=%d) %.4f\n", a.out.c_str(),
                static_cast<long long>(x.rows()), features.size(), result.kl_divergence, k, trustworthiness(x, result.embedding, k));
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    auto* cmd = root.add_subcommand("tsne", "feature table (CSV) -> 2-D t-SNE embedding (CSV); non-numeric columns are carried over");
    static TsneArgs a;
    cmd->add_option("--in", a.in, "input CSV with a header")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", a.out, "output CSV")->required();
    cmd->add_option("--perplexity", a.options.perplexity, "default 30");
    cmd->add_option("--iterations", a.options.iterations, "default 1000");
    cmd->add_flag("--exact", a.options.exact, "exact gradients (O(N^2); small N)");
    cmd->callback([] { run(a); });
});

}  // namespace t2imu::cli
