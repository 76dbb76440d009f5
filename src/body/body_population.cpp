#include "body/body_population.hpp"

#include <cmath>
#include <random>
#include <sstream>

#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

namespace {

constexpr double kTruncationSd = 3;  // draws beyond this many standard deviations are redrawn

MeanSd parse_mean_sd(const std::string& key, const std::string& value) {
    const size_t colon = value.find(':');
    if (colon == std::string::npos) throw Error("--body", key, "MEAN:SD", value);
    return {parse_body_number(value.substr(0, colon), key), parse_body_number(value.substr(colon + 1), key)};
}

// max_cv: the largest standard deviation as a share of the mean (adults' stature varies by about 0.04 of it, BMI by
// 0.16).
void check_mean_sd(const char* key, const MeanSd& v, double lowest, double highest, double max_cv) {
    if (v.mean < lowest || v.mean > highest)
        throw Error("--body", key, "a mean from " + std::to_string(lowest) + " to " + std::to_string(highest),
                    std::to_string(v.mean));
    if (!(v.sd >= 0) || v.sd > max_cv * v.mean)
        throw Error("--body", key, "a standard deviation from 0 to " + std::to_string(max_cv) + " of the mean",
                    std::to_string(v.sd));
}

// A standard normal draw within the truncation.
double truncated_normal(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    for (;;) {
        const double z = normal(rng);
        if (std::abs(z) <= kTruncationSd) return z;
    }
}

// Log-normal with the given mean and standard deviation (not those of the logarithm).
double log_normal(const MeanSd& v, double z) {
    const double sigma2 = std::log1p(v.sd * v.sd / (v.mean * v.mean));
    return std::exp(std::log(v.mean) - sigma2 / 2 + std::sqrt(sigma2) * z);
}

bool is_female(int i, double share) { return std::lround((i + 1) * share) > std::lround(i * share); }

}  // namespace

void BodyPopulation::validate() const {
    if (count < 1 || count > 1000) throw Error("--body", "population", "1 to 1000 bodies", std::to_string(count));
    if (!(female_share >= 0 && female_share <= 1))
        throw Error("--body", "female", "a share from 0 to 1", std::to_string(female_share));
    check_mean_sd("height_m", height_cm_male, 100, 230, 0.1);
    check_mean_sd("height_f", height_cm_female, 100, 230, 0.1);
    check_mean_sd("bmi_m", bmi_male, 12, 60, 0.3);
    check_mean_sd("bmi_f", bmi_female, 12, 60, 0.3);
}

BodyPopulation parse_body_population(const std::string& text) {
    BodyPopulation p;
    const NamedOverrides spelled = parse_named_overrides(text, "--body");
    const double count = parse_body_number(spelled.name, "population");
    if (count != std::floor(count) || count < 1 || count > 1000)
        throw Error("--body", "population", "1 to 1000 bodies", spelled.name);
    p.count = static_cast<int>(count);
    for (const auto& [key, value] : spelled.overrides) {
        if (key == "seed") {
            const double s = parse_body_number(value, "seed");
            if (s != std::floor(s) || s < 0 || s > 9e15) throw Error("--body", "seed", "a whole number >= 0", value);
            p.seed = static_cast<uint64_t>(s);
        } else if (key == "female") {
            p.female_share = parse_body_number(value, "female");
        } else if (key == "height_m") {
            p.height_cm_male = parse_mean_sd(key, value);
        } else if (key == "height_f") {
            p.height_cm_female = parse_mean_sd(key, value);
        } else if (key == "bmi_m") {
            p.bmi_male = parse_mean_sd(key, value);
        } else if (key == "bmi_f") {
            p.bmi_female = parse_mean_sd(key, value);
        } else {
            throw Error("--body", key + "=" + value,
                        "seed=S, female=F, height_m|height_f=CM:SD or bmi_m|bmi_f=MEAN:SD");
        }
    }
    p.validate();
    return p;
}

std::vector<BodySpec> sample_bodies(const BodyPopulation& population) {
    population.validate();
    const int digits = static_cast<int>(std::to_string(population.count - 1).size());
    std::vector<BodySpec> out;
    for (int i = 0; i < population.count; ++i) {
        std::seed_seq seq{static_cast<uint32_t>(population.seed), static_cast<uint32_t>(population.seed >> 32),
                          static_cast<uint32_t>(i)};
        std::mt19937_64 rng(seq);
        BodySpec b;
        b.sex = is_female(i, population.female_share) ? Sex::female : Sex::male;
        const bool female = b.sex == Sex::female;
        const MeanSd& height = female ? population.height_cm_female : population.height_cm_male;
        b.height_m = (height.mean + height.sd * truncated_normal(rng)) / 100.0;
        b.mass_kg = log_normal(female ? population.bmi_female : population.bmi_male, truncated_normal(rng)) *
                    b.height_m * b.height_m;
        std::ostringstream name;
        name << "pop" << std::string(digits - std::to_string(i).size(), '0') << i << "_h"
             << std::lround(b.height_m * 100) << "_m" << std::lround(b.mass_kg) << "_" << (female ? "f" : "m");
        b.name = name.str();
        out.push_back(b);
    }
    return out;
}

}  // namespace t2imu
