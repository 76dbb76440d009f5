#include "report/html_report.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "analysis/domain_gap.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "har/har_result.hpp"
#include "har/low_data_curve.hpp"
#include "imu/imu_dataset.hpp"
#include "report/figures.hpp"
#include "report/html_page.hpp"
#include "report/synth_section.hpp"

namespace t2imu {

namespace fs = std::filesystem;

namespace {

std::string stem(const fs::path& p) { return p.stem().string(); }

bool has(const CsvTable& t, const char* column) { return t.has_column(column); }

void har_section(const std::vector<std::pair<std::string, HarResult>>& results, Page& page) {
    if (results.empty()) return;
    page.body +=
        "<h2>Human activity recognition (DeepConvLSTM)</h2>\n<table><tr><th>result</th><th>balanced accuracy (%)</th>"
        "<th>macro F1 (%)</th><th>runs</th><th>classes</th></tr>\n";
    char buf[256];
    for (const auto& [name, r] : results) {
        const ScoreSummary ba = score_summary(r, &HarRun::balanced_accuracy), f1 = score_summary(r, &HarRun::macro_f1);
        std::snprintf(
            buf, sizeof buf,
            "<tr><td>%s</td><td>%.1f &plusmn; %.1f</td><td>%.1f &plusmn; %.1f</td><td>%zu</td><td>%s</td></tr>\n",
            html_escape(name).c_str(), 100 * ba.mean, 100 * ba.sd, 100 * f1.mean, 100 * f1.sd, r.runs.size(),
            html_escape(nlohmann::json(r.classes).dump()).c_str());
        page.body += buf;
    }
    page.body += "</table>\n";
    plot_balanced_accuracy(results, page.out_dir + "/balanced_accuracy.png");
    page.figure("balanced_accuracy.png", "Balanced accuracy per result (Fig. 3)");
    for (const auto& [name, r] : results) {
        plot_confusion(r, page.out_dir + "/confusion_" + name + ".png", "Confusion (recall per true class): " + name);
        page.figure("confusion_" + name + ".png",
                    "Confusion matrix, " + name + " (rows: true class, summed over runs)");
    }
}

// Per real set: the curve and its table (mean ± sd over the draws per K and arm, the best synthetic arm's gain).
void low_data_section(const std::vector<LowDataCurve>& curves, Page& page) {
    for (const LowDataCurve& c : curves) {
        page.body += "<h2>Low-data curve: " + html_escape(c.real_set) +
                     "</h2>\n<p>Balanced accuracy (%) with K real training subjects "
                     "(drawn anew for each draw, tested on the others), mean &plusmn; sd over the draws; K = 0 is "
                     "synthetic only.</p>\n"
                     "<table><tr><th>K</th>";
        for (const LowDataArm& a : c.arms) page.body += "<th>" + html_escape(a.name) + "</th>";
        page.body += "<th>best synthetic arm &minus; real only</th></tr>\n";
        char buf[96];
        for (const std::string& label : c.labels) {
            page.body += "<tr><td>" + html_escape(label) + "</td>";
            double best = -1;
            for (const LowDataArm& a : c.arms) {
                const LowDataPoint* p = a.at(label);
                std::string cell;
                if (p) {
                    const ScoreSummary s = p->balanced_accuracy();
                    std::snprintf(buf, sizeof buf, "%.1f &plusmn; %.1f (%zu)", 100 * s.mean, 100 * s.sd, s.runs.size());
                    cell = buf;
                    if (&a != &c.arms.front()) best = std::max(best, s.mean);
                }
                page.body += "<td>" + cell + "</td>";
            }
            const LowDataPoint* real = c.arms.front().at(label);
            buf[0] = '\0';
            if (real && best >= 0)
                std::snprintf(buf, sizeof buf, "%+.1f", 100 * (best - real->balanced_accuracy().mean));
            page.body += "<td>" + std::string(buf) + "</td></tr>\n";
        }
        page.body += "</table>\n";
        const std::string png = "low_data_" + c.real_set + ".png";
        plot_low_data_curve(c, page.out_dir + "/" + png);
        page.figure(png, "Low-data curve, " + c.real_set + ": one line per arm, the band ± one sd over the draws");
    }
}

// The heading of a synthesis folder: its path under the results folder, or the results folder's own name when
// it is the results folder ("" at a filesystem root).
std::string synth_title(const fs::path& synth_dir, const std::string& results_dir) {
    const std::string relative = fs::relative(synth_dir, results_dir).generic_string();
    return relative != "." ? relative : fs::weakly_canonical(results_dir).filename().string();
}

// What a results folder holds, found by content (so any layout of t2imu's outputs works): HAR results, domain
// gaps, synthesis reports, L_acc tables, t-SNE tables and up to three IMU traces.
struct FoundResults {
    std::vector<std::pair<std::string, HarResult>> har;
    std::vector<std::pair<std::string, DomainGap>> gaps;
    std::vector<SynthFolder> synth;
    std::vector<LowDataCurve> low_data;
    std::vector<std::pair<std::string, CsvTable>> lacc, tsne, traces;
};

void classify_json(const fs::path& p, const std::string& results_dir, FoundResults* found) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(read_file_text(p.string()));
    } catch (const std::exception&) {
        return;  // not a result of ours
    }
    if (!j.is_object()) return;
    if (is_har_result(j))
        found->har.push_back({stem(p), parse_har_result(j, p.string())});
    else if (is_low_data_curves(j)) {
        const std::vector<LowDataCurve> curves = parse_low_data_curves(j, p.string());
        found->low_data.insert(found->low_data.end(), curves.begin(), curves.end());
    } else if (j.contains("classifier_two_sample_test"))
        found->gaps.push_back({stem(p), parse_domain_gap(j, p.string())});
    else if (j.contains("per_activity") && j.contains("motions_kept"))
        found->synth.push_back(
            {p.parent_path().string(), synth_title(p.parent_path(), results_dir), parse_synth_report(j, p.string())});
}

void classify_csv(const fs::path& p, const std::string& results_dir, FoundResults* found) {
    CsvTable t;
    try {
        t = read_csv(p.string());
    } catch (const Error&) {
        return;
    }
    if (has(t, "group") && has(t, "change_percent"))
        found->lacc.push_back({stem(p), t});
    else if (has(t, "tsne_x") && has(t, "tsne_y"))
        found->tsne.push_back({stem(p), t});
    else if (!t.header.empty() && t.header[0] == "t" && has(t, "acc_x") && found->traces.size() < 3)
        found->traces.push_back({fs::relative(p, results_dir).string(), t});
}

FoundResults find_results(const std::string& results_dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(results_dir))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    FoundResults found;
    for (const fs::path& p : files) {
        if (p.extension() == ".json")
            classify_json(p, results_dir, &found);
        else if (p.extension() == ".csv")
            classify_csv(p, results_dir, &found);
    }
    return found;
}

void lacc_section(const std::vector<std::pair<std::string, CsvTable>>& tables, Page& page) {
    for (const auto& [name, t] : tables) {
        page.body += "<h2>Acceleration loss per activity category</h2>\n";
        plot_lacc_change(t, page.out_dir + "/lacc_" + name + ".png");
        page.figure("lacc_" + name + ".png", "Change of L_acc after fine-tuning per category (Fig. 1): " + name);
    }
}

void tsne_section(const std::vector<std::pair<std::string, CsvTable>>& tables, Page& page) {
    for (const auto& [name, t] : tables) {
        page.body += "<h2>t-SNE of catch22 features</h2>\n";
        std::string colour = has(t, "source") ? "source" : "";
        for (const std::string& h : t.header)
            if (colour.empty() && h != "tsne_x" && h != "tsne_y") colour = h;
        plot_tsne(t, colour, page.out_dir + "/tsne_" + name + ".png", "t-SNE, all windows: " + name);
        page.figure("tsne_" + name + ".png", "t-SNE of all windows, coloured by " + colour + " (Fig. 2): " + name);
        if (!has(t, "activity")) continue;
        const std::vector<std::string> high = {"running", "jogging", "jumping", "dancing"};
        try {
            plot_tsne(t, colour, page.out_dir + "/tsne_high_" + name + ".png",
                      "t-SNE, high-dynamic activities: " + name, "activity", high);
            page.figure("tsne_high_" + name + ".png",
                        "t-SNE of high-dynamic activities (running, jumping, dancing): " + name);
        } catch (const Error&) {
            // no high-dynamic windows in this table
        }
    }
}

void gap_section(const std::vector<std::pair<std::string, DomainGap>>& gaps, Page& page) {
    if (gaps.empty()) return;
    page.body +=
        "<h2>Domain gap (real vs synthetic)</h2>\n<table><tr><th>result</th><th>two-sample balanced "
        "accuracy</th><th>most different feature (KS)</th></tr>\n";
    char buf[512];
    for (const auto& [name, g] : gaps) {
        const FeatureDistance top = g.per_feature.empty() ? FeatureDistance{"-", 0, 0} : g.per_feature[0];
        std::snprintf(buf, sizeof buf, "<tr><td>%s</td><td>%.3f</td><td>%s (%.3f)</td></tr>\n",
                      html_escape(name).c_str(), g.overall.balanced_accuracy, html_escape(top.feature).c_str(), top.ks);
        page.body += buf;
    }
    page.body += "</table><p>0.5 = a classifier cannot tell real from synthetic windows; 1.0 = fully separable.</p>\n";
}

void trace_section(const std::vector<std::pair<std::string, CsvTable>>& traces, Page& page) {
    for (size_t i = 0; i < traces.size(); ++i) {
        if (i == 0) page.body += "<h2>IMU traces</h2>\n";
        const std::string png = "trace_" + std::to_string(i) + ".png";
        plot_imu_trace(traces[i].second, page.out_dir + "/" + png, traces[i].first);
        page.figure(png, "IMU signals: " + traces[i].first);
    }
}

std::string page_html(const std::string& results_dir, const Page& page) {
    return "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>t2imu report</title><style>"
           "body{font-family:sans-serif;max-width:1000px;margin:2em auto;}img{max-width:100%;}"
           "table{border-collapse:collapse;}td,th{border:1px solid #ccc;padding:4px 8px;}"
           ".job{border-top:1px solid #eee;margin:0.6em 0;}.job p{margin:0.3em "
           "0;}.outcome{font-size:90%;color:#444;}</style></head><body>\n"
           "<h1>t2imu report</h1>\n<p>Results from " +
           html_escape(results_dir) + "</p>\n" + page.body + "</body></html>\n";
}

}  // namespace

ReportSummary write_report(const std::string& results_dir, const std::string& report_dir, const std::string& real_dir) {
    if (!fs::is_directory(results_dir)) throw Error(results_dir, "folder", "a folder of results");
    claim_output_folder(report_dir);  // marked as t2imu's: a rerun replaces its pages (core/output_path.hpp)
    const FoundResults found = find_results(results_dir);
    Page page;
    page.out_dir = report_dir;
    const bool compare_real = !real_dir.empty() && !found.synth.empty();
    synth_section(found.synth, compare_real ? read_imu_dataset(real_dir) : std::vector<ImuRecording>{}, real_dir, page);
    low_data_section(found.low_data, page);
    har_section(found.har, page);
    lacc_section(found.lacc, page);
    tsne_section(found.tsne, page);
    gap_section(found.gaps, page);
    trace_section(found.traces, page);
    write_file_atomic(report_dir + "/index.html", page_html(results_dir, page));
    ReportSummary summary;
    summary.figures = page.figures;
    summary.synth_reports = static_cast<int>(found.synth.size());
    summary.har_results = static_cast<int>(found.har.size());
    summary.low_data_curves = static_cast<int>(found.low_data.size());
    summary.lacc_tables = static_cast<int>(found.lacc.size());
    summary.tsne_tables = static_cast<int>(found.tsne.size());
    summary.gap_results = static_cast<int>(found.gaps.size());
    summary.traces = static_cast<int>(found.traces.size());
    return summary;
}

}  // namespace t2imu
