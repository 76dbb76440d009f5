#include "analysis/tsne.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "core/error.hpp"

namespace t2imu {

namespace {

using Eigen::Vector2d;

// Affinities of one point to its candidates from their squared distances: the Gaussian bandwidth (precision
// beta) whose distribution has entropy log(perplexity), by bisection (scikit-learn's tolerance and limit).
void conditional_affinities(const std::vector<double>& d2, double perplexity, std::vector<double>* p) {
    const double target = std::log(perplexity);
    double beta = 1, lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    p->assign(d2.size(), 0.0);
    for (int it = 0; it < 100; ++it) {
        double sum = 0, weighted = 0;
        for (size_t j = 0; j < d2.size(); ++j) {
            (*p)[j] = std::exp(-d2[j] * beta);
            sum += (*p)[j];
        }
        if (sum == 0) sum = 1e-8;
        for (size_t j = 0; j < d2.size(); ++j) {
            (*p)[j] /= sum;
            weighted += d2[j] * (*p)[j];
        }
        const double entropy = std::log(sum) + beta * weighted;
        if (std::fabs(entropy - target) <= 1e-5) break;
        if (entropy > target) {
            lo = beta;
            beta = std::isinf(hi) ? beta * 2 : (beta + hi) / 2;
        } else {
            hi = beta;
            beta = std::isinf(lo) ? beta / 2 : (beta + lo) / 2;
        }
    }
}

double squared_distance(const PointMatrix& x, Eigen::Index i, Eigen::Index j) {
    return (x.row(i) - x.row(j)).squaredNorm();
}

// Joint affinities P (symmetrised, summing to 1) as a sparse list per row: (j, p_ij).
using SparseRows = std::vector<std::vector<std::pair<int, double>>>;

SparseRows joint_affinities(const PointMatrix& x, double perplexity, bool exact) {
    const int n = static_cast<int>(x.rows());
    const int k = exact ? n - 1 : std::min(n - 1, static_cast<int>(3 * perplexity + 1));
    SparseRows rows(static_cast<size_t>(n));
    std::vector<double> d2, p;
    std::vector<std::pair<double, int>> all(static_cast<size_t>(n - 1));
    for (int i = 0; i < n; ++i) {
        int m = 0;
        for (int j = 0; j < n; ++j)
            if (j != i) all[static_cast<size_t>(m++)] = {squared_distance(x, i, j), j};
        std::nth_element(all.begin(), all.begin() + (k - 1), all.end());
        std::sort(all.begin(), all.begin() + k);
        d2.resize(static_cast<size_t>(k));
        for (int c = 0; c < k; ++c) d2[static_cast<size_t>(c)] = all[static_cast<size_t>(c)].first;
        conditional_affinities(d2, perplexity, &p);
        for (int c = 0; c < k; ++c)
            rows[static_cast<size_t>(i)].push_back({all[static_cast<size_t>(c)].second, p[static_cast<size_t>(c)]});
    }
    // P = (P + P^T) / sum.
    std::vector<std::vector<std::pair<int, double>>> sym(static_cast<size_t>(n));
    std::vector<double> accum(static_cast<size_t>(n), 0.0);
    std::vector<int> touched;
    double total = 0;
    SparseRows transposed(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
        for (const auto& [j, v] : rows[static_cast<size_t>(i)]) transposed[static_cast<size_t>(j)].push_back({i, v});
    for (int i = 0; i < n; ++i) {
        touched.clear();
        for (const SparseRows* src : {&rows, &transposed})
            for (const auto& [j, v] : (*src)[static_cast<size_t>(i)]) {
                if (accum[static_cast<size_t>(j)] == 0) touched.push_back(j);
                accum[static_cast<size_t>(j)] += v;
            }
        std::sort(touched.begin(), touched.end());
        for (int j : touched) {
            sym[static_cast<size_t>(i)].push_back({j, accum[static_cast<size_t>(j)]});
            total += accum[static_cast<size_t>(j)];
            accum[static_cast<size_t>(j)] = 0;
        }
    }
    for (auto& row : sym)
        for (auto& e : row) e.second /= std::max(total, 1e-300);
    return sym;
}

PointMatrix pca_initialisation(const PointMatrix& x) {
    const Eigen::RowVectorXd mean = x.colwise().mean();
    const PointMatrix centred = x.rowwise() - mean;
    const Eigen::MatrixXd cov = centred.transpose() * centred;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov);
    const Eigen::Index d = cov.rows();
    PointMatrix y(x.rows(), 2);
    for (int c = 0; c < 2; ++c) {
        Eigen::VectorXd v = d > c ? Eigen::VectorXd(eig.eigenvectors().col(d - 1 - c)) : Eigen::VectorXd::Zero(d);
        Eigen::Index big = 0;
        v.cwiseAbs().maxCoeff(&big);
        if (v[big] < 0) v = -v;  // a deterministic sign, as scikit-learn's svd_flip
        y.col(c) = centred * v;
    }
    const double sd = std::sqrt((y.col(0).array() - y.col(0).mean()).square().mean());
    return sd > 0 ? PointMatrix(y / sd * 1e-4) : PointMatrix(y * 0.0);
}

// A quadtree over the embedding, rebuilt every iteration: each cell keeps its points' count and centre of mass.
class QuadTree {
public:
    explicit QuadTree(const PointMatrix& y) : y_(y) {
        const Vector2d lo = y.colwise().minCoeff().transpose(), hi = y.colwise().maxCoeff().transpose();
        nodes_.push_back(Node{(lo + hi) / 2, std::max((hi - lo).maxCoeff() / 2, 1e-12) * (1 + 1e-9)});
        for (int i = 0; i < y.rows(); ++i) insert(0, i, 0);
    }

    // Repulsion on point i: sum of q^2 (y_i - y_c) and of q over all other points (q = 1 / (1 + d^2)).
    void repulsion(int i, double theta, Vector2d* force, double* z) const {
        const Vector2d yi = y_.row(i).transpose();
        std::vector<int> stack = {0};
        while (!stack.empty()) {
            const Node& node = nodes_[static_cast<size_t>(stack.back())];
            stack.pop_back();
            if (node.count == 0) continue;
            const Vector2d d = yi - node.mass_centre;
            const double d2 = d.squaredNorm();
            if (node.leaf || (2 * node.half_width) * (2 * node.half_width) < theta * theta * d2) {
                const double others = node.count - (node.leaf && node.holds(i) ? 1 : 0);
                const double q = 1 / (1 + d2);
                *z += others * q;
                *force += others * q * q * d;
            } else {
                for (int c : node.child) stack.push_back(c);
            }
        }
    }

private:
    struct Node {
        Vector2d centre;
        double half_width;
        Vector2d mass_centre = Vector2d::Zero();
        double count = 0;
        bool leaf = true;
        std::vector<int> points = {};  // a leaf's points (more than one only when they coincide)
        int child[4] = {-1, -1, -1, -1};
        bool holds(int i) const { return std::find(points.begin(), points.end(), i) != points.end(); }
    };

    void insert(int n, int i, int depth) {
        const Vector2d p = y_.row(i).transpose();
        Node* node = &nodes_[static_cast<size_t>(n)];
        node->mass_centre = (node->mass_centre * node->count + p) / (node->count + 1);
        node->count += 1;
        if (node->leaf) {
            const bool same = !node->points.empty() && (y_.row(node->points[0]).transpose() - p).squaredNorm() == 0;
            if (node->points.empty() || same || depth > 60) {
                node->points.push_back(i);
                return;
            }
            split(n);
            node = &nodes_[static_cast<size_t>(n)];
        }
        const int c = quadrant(*node, p);
        insert(node->child[c], i, depth + 1);
    }

    void split(int n) {
        const Vector2d centre = nodes_[static_cast<size_t>(n)].centre;
        const double hw = nodes_[static_cast<size_t>(n)].half_width / 2;
        for (int c = 0; c < 4; ++c) {
            const Vector2d offset((c & 1) ? hw : -hw, (c & 2) ? hw : -hw);
            nodes_.push_back(Node{centre + offset, hw});
            nodes_[static_cast<size_t>(n)].child[c] = static_cast<int>(nodes_.size()) - 1;
        }
        Node& node = nodes_[static_cast<size_t>(n)];
        node.leaf = false;
        const std::vector<int> moved = std::move(node.points);
        node.points.clear();
        for (int m : moved) {
            const int c = quadrant(nodes_[static_cast<size_t>(n)], y_.row(m).transpose());
            const int child = nodes_[static_cast<size_t>(n)].child[c];
            Node& ch = nodes_[static_cast<size_t>(child)];
            ch.mass_centre = (ch.mass_centre * ch.count + y_.row(m).transpose()) / (ch.count + 1);
            ch.count += 1;
            ch.points.push_back(m);
        }
    }

    static int quadrant(const Node& node, const Vector2d& p) {
        return (p.x() > node.centre.x() ? 1 : 0) + (p.y() > node.centre.y() ? 2 : 0);
    }

    const PointMatrix& y_;
    std::vector<Node> nodes_;
};

// Gradient of KL(P || Q) (times 1, exaggeration applied to P) and the divergence itself.
double gradient(const SparseRows& p, double exaggeration, const PointMatrix& y, const TsneOptions& o,
                PointMatrix* grad) {
    const int n = static_cast<int>(y.rows());
    grad->setZero(n, 2);
    std::vector<Vector2d> repulsive(static_cast<size_t>(n), Vector2d::Zero());
    double z = 0;
    if (o.exact || o.theta <= 0) {
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                if (i == j) continue;
                const Vector2d d = (y.row(i) - y.row(j)).transpose();
                const double q = 1 / (1 + d.squaredNorm());
                z += q;
                repulsive[static_cast<size_t>(i)] += q * q * d;
            }
    } else {
        const QuadTree tree(y);
        for (int i = 0; i < n; ++i) tree.repulsion(i, o.theta, &repulsive[static_cast<size_t>(i)], &z);
    }
    double kl = 0;
    for (int i = 0; i < n; ++i) {
        Vector2d attractive = Vector2d::Zero();
        for (const auto& [j, pij] : p[static_cast<size_t>(i)]) {
            const Vector2d d = (y.row(i) - y.row(j)).transpose();
            const double q = 1 / (1 + d.squaredNorm());
            attractive += exaggeration * pij * q * d;
            kl += pij * std::log(std::max(pij, 1e-12) / std::max(q / z, 1e-12));
        }
        grad->row(i) = 4 * (attractive - repulsive[static_cast<size_t>(i)] / z).transpose();
    }
    return kl;
}

}  // namespace

void TsneOptions::validate() const {
    if (!(perplexity > 0 && perplexity <= 1e6))
        throw Error("tsne", "--perplexity", "above 0 and below a third of the points", std::to_string(perplexity));
    if (iterations < 1 || iterations > 1000000)
        throw Error("tsne", "--iterations", "1 to 10^6", std::to_string(iterations));
    if (exaggeration_iterations < 0 || exaggeration_iterations > iterations)
        throw Error("tsne", "exaggeration iterations", "0 to the iterations", std::to_string(exaggeration_iterations));
    if (!(early_exaggeration >= 1 && early_exaggeration <= 1000))
        throw Error("tsne", "early exaggeration", "1 to 1000", std::to_string(early_exaggeration));
    if (!(theta >= 0 && theta <= 1)) throw Error("tsne", "theta", "0 (exact) to 1", std::to_string(theta));
}

TsneResult tsne(const PointMatrix& x, const TsneOptions& o) {
    const Eigen::Index n = x.rows();
    if (n < 4) throw Error("tsne", "points", "at least 4 points", std::to_string(n));
    if (!x.allFinite()) throw Error("tsne", "values", "finite numbers", "NaN or inf");
    if (!(o.perplexity > 0) || o.perplexity * 3 >= static_cast<double>(n))
        throw Error("tsne", "perplexity", "0 < perplexity < points / 3", std::to_string(o.perplexity));
    const SparseRows p = joint_affinities(x, o.perplexity, o.exact);
    PointMatrix y = pca_initialisation(x), update = PointMatrix::Zero(n, 2), gains = PointMatrix::Ones(n, 2), grad;
    const double learning_rate = std::max(static_cast<double>(n) / o.early_exaggeration, 50.0);
    TsneResult result;
    for (int it = 0; it < o.iterations; ++it) {
        const bool early = it < o.exaggeration_iterations;
        result.kl_divergence = gradient(p, early ? o.early_exaggeration : 1.0, y, o, &grad);
        const double momentum = early ? 0.5 : 0.8;
        for (Eigen::Index i = 0; i < n; ++i)
            for (int c = 0; c < 2; ++c) {
                double& g = gains(i, c);
                g = (update(i, c) * grad(i, c) < 0) ? g + 0.2 : g * 0.8;
                g = std::max(g, 0.01);
                update(i, c) = momentum * update(i, c) - learning_rate * g * grad(i, c);
                y(i, c) += update(i, c);
            }
    }
    result.embedding = y;
    return result;
}

double trustworthiness(const PointMatrix& x, const PointMatrix& e, int k) {
    const Eigen::Index n = x.rows();
    if (e.rows() != n) throw Error("trustworthiness", "rows", std::to_string(n), std::to_string(e.rows()));
    if (k < 1 || 2 * n - 3 * k - 1 <= 0)
        throw Error("trustworthiness", "k", "1 <= k < (2n - 1) / 3", std::to_string(k));
    std::vector<int> order(static_cast<size_t>(n)), rank(static_cast<size_t>(n));
    std::vector<double> d(static_cast<size_t>(n));
    double sum = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        for (Eigen::Index j = 0; j < n; ++j)
            d[static_cast<size_t>(j)] = j == i ? std::numeric_limits<double>::infinity() : squared_distance(x, i, j);
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return d[static_cast<size_t>(a)] < d[static_cast<size_t>(b)]; });
        for (Eigen::Index r = 0; r < n; ++r)
            rank[static_cast<size_t>(order[static_cast<size_t>(r)])] = static_cast<int>(r) + 1;
        for (Eigen::Index j = 0; j < n; ++j)
            d[static_cast<size_t>(j)] = j == i ? std::numeric_limits<double>::infinity() : squared_distance(e, i, j);
        std::iota(order.begin(), order.end(), 0);
        std::partial_sort(order.begin(), order.begin() + k, order.end(),
                          [&](int a, int b) { return d[static_cast<size_t>(a)] < d[static_cast<size_t>(b)]; });
        for (int c = 0; c < k; ++c) sum += std::max(rank[static_cast<size_t>(order[static_cast<size_t>(c)])] - k, 0);
    }
    const double nn = static_cast<double>(n);
    return 1 - sum * 2 / (nn * k * (2 * nn - 3 * k - 1));
}

}  // namespace t2imu
