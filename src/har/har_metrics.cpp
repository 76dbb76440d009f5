#include "har/har_metrics.hpp"

#include <cmath>

#include "core/error.hpp"

namespace t2imu {

Confusion confusion_matrix(const std::vector<int>& truth, const std::vector<int>& predicted, int classes) {
    if (truth.size() != predicted.size())
        throw Error("metrics", "predictions", std::to_string(truth.size()), std::to_string(predicted.size()));
    Confusion c(static_cast<size_t>(classes), std::vector<long>(static_cast<size_t>(classes), 0));
    for (size_t i = 0; i < truth.size(); ++i) {
        if (truth[i] < 0 || truth[i] >= classes || predicted[i] < 0 || predicted[i] >= classes)
            throw Error("metrics", "class", "0.." + std::to_string(classes - 1));
        ++c[static_cast<size_t>(truth[i])][static_cast<size_t>(predicted[i])];
    }
    return c;
}

std::vector<double> per_class_recall(const Confusion& c) {
    std::vector<double> r;
    for (size_t k = 0; k < c.size(); ++k) {
        long total = 0;
        for (long v : c[k]) total += v;
        r.push_back(total ? static_cast<double>(c[k][k]) / static_cast<double>(total) : std::nan(""));
    }
    return r;
}

double balanced_accuracy(const Confusion& c) {
    double sum = 0;
    int present = 0;
    for (double r : per_class_recall(c))
        if (!std::isnan(r)) sum += r, ++present;
    return present ? sum / present : std::nan("");
}

double macro_f1(const Confusion& c) {
    double sum = 0;
    int present = 0;
    for (size_t k = 0; k < c.size(); ++k) {
        long row = 0, col = 0;
        for (size_t j = 0; j < c.size(); ++j) row += c[k][j], col += c[j][k];
        if (row == 0) continue;
        ++present;
        const double tp = static_cast<double>(c[k][k]);
        sum += tp == 0 ? 0.0 : 2 * tp / static_cast<double>(row + col);
    }
    return present ? sum / present : std::nan("");
}

}  // namespace t2imu
