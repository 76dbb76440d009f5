// Classification metrics of HAR papers, from a confusion matrix (rows = true class, columns = predicted).
// Classes absent from the test set (a zero row) are left out of the averages, as scikit-learn's
// balanced_accuracy_score does.
#pragma once
#include <vector>

namespace t2imu {

using Confusion = std::vector<std::vector<long>>;

Confusion confusion_matrix(const std::vector<int>& truth, const std::vector<int>& predicted, int classes);
std::vector<double> per_class_recall(const Confusion& c);  // NaN for a class absent from the truth
double balanced_accuracy(const Confusion& c);              // mean recall over present classes
double macro_f1(const Confusion& c);                       // mean F1 over present classes

}  // namespace t2imu
