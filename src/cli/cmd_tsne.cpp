// t2imu tsne: a feature table -> a 2-D t-SNE embedding (and its trustworthiness).
#include <algorithm>
#include <cstdio>
#include <set>

#include "analysis/catch22_table.hpp"
#include "analysis/tsne_table.hpp"
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/csv.hpp"
#include "core/output_path.hpp"

namespace t2imu::cli {

namespace {

struct TsneArgs {
    std::string in, out;
    TsneOptions options;
};

// The window table's label columns (catch22_table.hpp) and any non-numeric column are carried over beside
// tsne_x, tsne_y; the rest are the features.
void run(const TsneArgs& a) {
    check_usage([&] {
        a.options.validate();
        check_output(a.out, "--out", OutputKind::file, {a.in});
    });
    const std::set<std::string> labels(kWindowLabelColumns.begin(), kWindowLabelColumns.end());
    const TsneTable t = tsne_table(read_csv(a.in), labels, a.options, a.in);
    write_csv(a.out, t.embedding);
    const int k = std::min<int>(5, static_cast<int>((2 * t.features.rows() - 2) / 3));
    std::printf("%s: %lld points, %zu features, KL %.4f, trustworthiness (k=%d) %.4f\n", a.out.c_str(),
                static_cast<long long>(t.features.rows()), t.feature_columns, t.result.kl_divergence, k,
                trustworthiness(t.features, t.result.embedding, k));
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    auto* cmd = root.add_subcommand(
        "tsne", "feature table (CSV) -> 2-D t-SNE embedding (CSV); non-numeric columns are carried over");
    auto& a = option_values<TsneArgs>();
    cmd->add_option("--in", a.in, "input CSV with a header")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", a.out, "output CSV")->required();
    cmd->add_option("--perplexity", a.options.perplexity, "default 30");
    cmd->add_option("--iterations", a.options.iterations, "default 1000");
    cmd->add_flag("--exact", a.options.exact, "exact gradients (O(N^2); small N)");
    cmd->callback([&a] { run(a); });
});

}  // namespace t2imu::cli
