#include "analysis/lacc_analysis.hpp"

#include <cmath>
#include <cstdio>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/number_text.hpp"

namespace t2imu {

std::vector<LaccSample> read_lacc_csv(const std::string& path) {
    const CsvTable t = read_csv(path);
    const size_t id = t.column("id"), caption = t.column("caption"), l = t.column("l_acc");
    std::vector<LaccSample> out;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const double v = t.number(r, l);
        if (!std::isfinite(v) || v < 0)
            throw Error(path, "l_acc row " + std::to_string(r + 2), "a finite, non-negative number", t.rows[r][l]);
        out.push_back({t.rows[r][id], t.rows[r][caption], v});
    }
    return out;
}

namespace {
void add(LaccGroup& g, double before, double after) {
    g.before = (g.before * static_cast<double>(g.samples) + before) / static_cast<double>(g.samples + 1);
    g.after = (g.after * static_cast<double>(g.samples) + after) / static_cast<double>(g.samples + 1);
    ++g.samples;
}
}  // namespace

LaccAnalysis analyse_lacc(const std::vector<LaccSample>& before, const std::vector<LaccSample>& after,
                          const ActivityCategorizer& categorizer) {
    std::map<std::string, const LaccSample*> by_id;
    for (const LaccSample& s : after) by_id[s.id] = &s;
    std::map<std::string, LaccGroup> groups;
    LaccAnalysis a;
    a.high_dynamic.name = "high_dynamic";
    a.low_dynamic.name = "low_dynamic";
    a.all.name = "all";
    for (const LaccSample& b : before) {
        const auto it = by_id.find(b.id);
        if (it == by_id.end()) throw Error("l_acc", "id " + b.id, "the same samples in both files");
        const std::string category = categorizer.categorize(b.caption).category;
        add(groups[category], b.l_acc, it->second->l_acc);
        add(a.all, b.l_acc, it->second->l_acc);
        if (category != "Other")
            add(is_high_dynamic(category) ? a.high_dynamic : a.low_dynamic, b.l_acc, it->second->l_acc);
    }
    if (before.size() != after.size())
        throw Error("l_acc", "rows", std::to_string(before.size()) + " samples in both files",
                    std::to_string(after.size()));
    std::vector<std::string> order = kActivityCategories;
    order.push_back("Other");
    for (const std::string& c : order)
        if (groups.count(c)) {
            groups[c].name = c;
            a.categories.push_back(groups[c]);
        }
    return a;
}

std::string lacc_analysis_csv(const LaccAnalysis& a) {
    std::string out = "group,samples,l_acc_before,l_acc_after,change_percent\n";
    std::vector<LaccGroup> rows = a.categories;
    rows.push_back(a.high_dynamic);
    rows.push_back(a.low_dynamic);
    rows.push_back(a.all);
    for (const LaccGroup& g : rows)
        out += g.name + "," + std::to_string(g.samples) + "," + general_text(g.before, 6) + "," +
               general_text(g.after, 6) + "," + fixed_text(g.change_percent(), 2) + "\n";
    return out;
}

}  // namespace t2imu
