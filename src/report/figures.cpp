#include "report/figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/error.hpp"
#include "imu/imu_dataset.hpp"
#include "report/gnuplot.hpp"

namespace t2imu {

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// Points and medians of one source's statistics: rows "x acc_sd dominant_hz" around x = activity index + offset.
void add_stats_rows(const std::vector<SignalStats>& stats, double x, GnuplotData& points, GnuplotData& medians) {
    for (size_t k = 0; k < stats.size(); ++k) {
        const double jitter =
            0.12 * (std::fmod(0.618034 * static_cast<double>(k), 1.0) - 0.5);  // spread, same every run
        points.rows.push_back({number(x + jitter), number(stats[k].acc_sd_m_s2), number(stats[k].dominant_hz)});
    }
    if (!stats.empty())
        medians.rows.push_back({number(x), number(median_of(stats, &SignalStats::acc_sd_m_s2)),
                                number(median_of(stats, &SignalStats::dominant_hz))});
}

}  // namespace

void plot_lacc_change(const CsvTable& lacc, const std::string& png) {
    GnuplotData d{"bars", {}};
    const size_t g = lacc.column("group"), c = lacc.column("change_percent"), n = lacc.column("samples");
    double lo = 0, hi = 0;  // bars grow from zero, so the range must hold it
    for (size_t r = 0; r < lacc.rows.size(); ++r) {
        lo = std::min(lo, lacc.number(r, c));
        hi = std::max(hi, lacc.number(r, c));
    }
    const double pad = 0.1 * std::max(hi - lo, 1.0);
    for (size_t r = 0; r < lacc.rows.size(); ++r) {
        const std::string& name = lacc.rows[r][g];
        const bool aggregate = name == "high_dynamic" || name == "low_dynamic" || name == "all";
        d.rows.push_back({std::to_string(r), gnuplot_label(name + " (" + lacc.rows[r][n] + ")"), lacc.rows[r][c],
                          aggregate ? "2" : "1"});
    }
    render_png(png, {d},
               "set title 'Change of L_{acc} after fine-tuning, per activity category (samples)'\n"
               "set ylabel 'L_{acc} change (%)'\nset yrange [" +
                   number(lo - pad) + ":" + number(hi + pad) +
                   "]\n"
                   "set style fill solid 0.8 border -1\nset boxwidth 0.7\n"
                   "set xtics rotate by -35 left\nset grid ytics\nset xzeroaxis lt -1\nunset key\n"
                   "set palette defined (1 '#3b75af', 2 '#e08a2c')\nunset colorbox\n"
                   "plot $bars using 1:3:4:xtic(2) with boxes lc palette");
}

void plot_tsne(const CsvTable& t, const std::string& colour_column, const std::string& png, const std::string& title,
               const std::string& filter_column, const std::vector<std::string>& keep) {
    const size_t x = t.column("tsne_x"), y = t.column("tsne_y"), c = t.column(colour_column);
    const size_t f = filter_column.empty() ? 0 : t.column(filter_column);
    std::map<std::string, GnuplotData> groups;
    for (const auto& row : t.rows) {
        if (!keep.empty() && std::find(keep.begin(), keep.end(), row[f]) == keep.end()) continue;
        GnuplotData& d = groups[row[c]];
        d.rows.push_back({row[x], row[y]});
    }
    if (groups.empty()) throw Error(png, "points", "at least one point to plot");
    std::vector<GnuplotData> data;
    std::string plot = "plot ";
    int k = 0;
    for (auto& [name, d] : groups) {
        d.name = "g" + std::to_string(k);
        plot += std::string(k ? ", " : "") + "$" + d.name + " using 1:2 with points pt 7 ps 0.5 title " +
                gnuplot_label(name);
        data.push_back(d);
        ++k;
    }
    render_png(png, data,
               "set title " + gnuplot_label(title) +
                   "\nset xlabel 't-SNE 1'\nset ylabel 't-SNE 2'\nset key outside right\n" + plot,
               900, 700);
}

void plot_balanced_accuracy(const std::vector<std::pair<std::string, HarResult>>& results, const std::string& png) {
    GnuplotData d{"acc", {}};
    for (size_t i = 0; i < results.size(); ++i) {
        const ScoreSummary ba = score_summary(results[i].second, &HarRun::balanced_accuracy);
        d.rows.push_back(
            {std::to_string(i), gnuplot_label(results[i].first), number(100 * ba.mean), number(100 * ba.sd)});
    }
    render_png(
        png, {d},
        "set title 'Balanced accuracy (mean and standard deviation over runs)'\nset ylabel 'balanced accuracy (%)'\n"
        "set yrange [0:100]\nset style fill solid 0.8 border -1\nset boxwidth 0.6\nset grid ytics\nunset key\n"
        "set xtics rotate by -25 left\n"
        "plot $acc using 1:3:xtic(2) with boxes lc rgb '#3b75af', $acc using 1:3:4 with yerrorbars lc rgb 'black' pt "
        "-1");
}

void plot_confusion(const HarResult& result, const std::string& png, const std::string& title) {
    const std::vector<std::string>& classes = result.classes;
    const Confusion m = summed_confusion(result);
    GnuplotData d{"cm", {}};
    std::string xtics;
    for (size_t i = 0; i < classes.size(); ++i) {
        long total = 0;
        for (long v : m[i]) total += v;
        for (size_t j = 0; j < classes.size(); ++j)
            d.rows.push_back({std::to_string(j), std::to_string(i),
                              number(total ? static_cast<double>(m[i][j]) / static_cast<double>(total) : 0.0)});
        d.rows.push_back({});  // gnuplot's scan separator
        xtics += std::string(i ? ", " : "") + gnuplot_label(classes[i]) + " " + std::to_string(i);
    }
    render_png(png, {d},
               "set title " + gnuplot_label(title) + "\nset xlabel 'predicted'\nset ylabel 'true'\nset xtics (" +
                   xtics +
                   ") rotate by -35 left\n"
                   "set ytics (" +
                   xtics +
                   ")\nset yrange [] reverse\nset cbrange [0:1]\nset palette defined (0 'white', 1 '#3b75af')\n"
                   "set view map\nplot $cm using 1:2:3 with image notitle, $cm using 1:2:(sprintf('%.2f', $3)) with "
                   "labels notitle",
               760, 680);
}

void plot_low_data_curve(const LowDataCurve& curve, const std::string& png) {
    if (curve.labels.empty() || curve.arms.empty())
        throw Error(png, "low-data curve", "at least one K and one arm to plot");
    static const char* colours[] = {"#444444", "#3b75af", "#e1812c", "#3a923a", "#c03d3e", "#9372b2"};
    std::vector<GnuplotData> data;
    std::string plot = "plot ";
    std::string xtics;
    for (size_t x = 0; x < curve.labels.size(); ++x)
        xtics += std::string(x ? ", " : "") + gnuplot_label(curve.labels[x]) + " " + std::to_string(x);
    for (size_t a = 0; a < curve.arms.size(); ++a) {
        GnuplotData d{"arm" + std::to_string(a), {}};
        for (size_t x = 0; x < curve.labels.size(); ++x)
            if (const LowDataPoint* p = curve.arms[a].at(curve.labels[x])) {
                const ScoreSummary s = p->balanced_accuracy();
                d.rows.push_back({std::to_string(x), number(100 * s.mean), number(100 * (s.mean - s.sd)),
                                  number(100 * (s.mean + s.sd))});
            }
        if (d.rows.empty()) continue;
        const std::string colour = std::string("lc rgb '") + colours[a % 6] + "'";
        plot += std::string(data.empty() ? "" : ", ") + "$" + d.name + " using 1:3:4 with filledcurves " + colour +
                " fs transparent solid 0.15 notitle, $" + d.name + " using 1:2 with linespoints lw 2 pt 7 " + colour +
                " title " + gnuplot_label(curve.arms[a].name);
        data.push_back(d);
    }
    render_png(
        png, data,
        "set title " +
            gnuplot_label("Low-data curve, " + curve.real_set + ": balanced accuracy against real training subjects") +
            "\nset xlabel 'K real training subjects'\nset ylabel 'balanced accuracy (%)'\nset xtics (" + xtics +
            ")\nset xrange [-0.3:" + std::to_string(curve.labels.size() - 1) +
            ".3]\nset grid ytics\nset key bottom right\n" + plot);
}

void plot_signal_stats(const std::vector<ActivityStats>& groups, const std::string& png, const std::string& title) {
    if (groups.empty()) throw Error(png, "activities", "at least one activity to plot");
    bool has_real = false;
    for (const ActivityStats& g : groups) has_real = has_real || !g.real.empty();
    const double offset = has_real ? 0.2 : 0.0;  // synthetic left of the tick, real right of it
    GnuplotData syn{"syn", {}}, real{"real", {}}, syn_median{"msyn", {}}, real_median{"mreal", {}};
    std::string xtics;
    for (size_t i = 0; i < groups.size(); ++i) {
        add_stats_rows(groups[i].synthetic, static_cast<double>(i) - offset, syn, syn_median);
        add_stats_rows(groups[i].real, static_cast<double>(i) + offset, real, real_median);
        xtics += std::string(i ? ", " : "") + gnuplot_label(groups[i].activity) + " " + std::to_string(i);
    }
    const auto panel = [&](const std::string& ylabel, int column) {
        const std::string c = std::to_string(column);
        std::string plot = "set ylabel '" + ylabel + "'\nplot $syn using 1:" + c +
                           " with points pt 7 ps 0.6 lc rgb '#3b75af' title 'synthetic', "
                           "$msyn using 1:" +
                           c + ":(0.15) with xerrorbars pt -1 lw 3 lc rgb '#1d3f63' title 'median'";
        if (has_real)
            plot += ", $real using 1:" + c +
                    " with points pt 7 ps 0.6 lc rgb '#e08a2c' title 'real', "
                    "$mreal using 1:" +
                    c + ":(0.15) with xerrorbars pt -1 lw 3 lc rgb '#8a4f10' notitle";
        return plot + "\n";
    };
    std::vector<GnuplotData> data = {syn, syn_median};
    if (has_real) data.insert(data.end(), {real, real_median});
    render_png(png, data,
               "set multiplot layout 1,2 title " + gnuplot_label(title) +
                   "\nset grid ytics\nset key outside bottom center horizontal\n"
                   "set yrange [0:*]\nset offsets 0, 0, graph 0.08, 0\n"
                   "set xrange [-0.6:" +
                   number(static_cast<double>(groups.size()) - 0.4) + "]\nset xtics (" + xtics +
                   ") rotate by -35 left\n" + panel("|acc| standard deviation (m/s^2)", 2) +
                   panel("dominant frequency of |acc| (Hz)", 3) + "unset multiplot",
               1000, 460);
}

void plot_imu_trace(const CsvTable& rec, const std::string& png, const std::string& title) {
    GnuplotData d{"imu", {}};
    std::vector<size_t> cols;  // t, then acc xyz and gyr xyz: the gnuplot columns 1 to 7 below
    for (const std::string& name : imu_sample_columns()) cols.push_back(rec.column(name));
    for (const auto& row : rec.rows) {
        std::vector<std::string> r;
        for (size_t c : cols) r.push_back(row[c]);
        d.rows.push_back(r);
    }
    render_png(png, {d},
               "set multiplot layout 2,1 title " + gnuplot_label(title) +
                   "\nset grid\nset key outside right\n"
                   "set ylabel 'acc (m/s^2)'\nplot $imu using 1:2 w l t 'x', $imu using 1:3 w l t 'y', $imu using 1:4 "
                   "w l t 'z'\n"
                   "set xlabel 't (s)'\nset ylabel 'gyr (rad/s)'\nplot $imu using 1:5 w l t 'x', $imu using 1:6 w l t "
                   "'y', $imu using 1:7 w l t 'z'\n"
                   "unset multiplot",
               900, 640);
}

}  // namespace t2imu
