// Bodies drawn from a population: as many bodies as asked for, sampled from published anthropometric
// statistics, where the paper's eight sit at the corners of its Table 1.
//
// Per sex: stature (cm) is normal, body mass index (kg/m^2) log-normal and independent of stature (BMI is
// built to be nearly uncorrelated with height), mass = BMI x stature^2. Both are truncated at 3 standard
// deviations (redrawn), so no draw leaves the range of real adults.
//
// Defaults: the means are the paper's average bodies (Häusler et al., Table 1: men 178.9 cm / 85.8 kg,
// women 165.8 cm / 69.2 kg, i.e. BMI 26.8 and 25.2), so the population is centred where the paper's eight
// bodies are; the spreads are the adult standard deviations of the US National Health Survey (NCHS, Vital and
// Health Statistics Series 11 No. 8, 1965, ages 18-79): stature 2.85 in (men) and 2.58 in (women), weight
// 27.73 lb, taken as a BMI spread at the mean stature (12.58 kg / 1.789^2 = 3.93 men, / 1.658^2 = 4.58 women).
// A study whose subjects differ (young students, older adults) sets its own means and spreads.
//
// Body i's draws depend only on (seed, i) and its sex only on (i, female share), so population:4 is the first
// four bodies of population:8 with the same seed.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "body/body_spec.hpp"

namespace t2imu {

struct MeanSd {
    double mean = 0, sd = 0;
};

struct BodyPopulation {
    int count = 8;
    uint64_t seed = 0;
    double female_share = 0.5;  // exact: body i is female where round((i+1) F) > round(i F)
    MeanSd height_cm_male{178.9, 7.24}, height_cm_female{165.8, 6.55};
    MeanSd bmi_male{26.81, 3.93}, bmi_female{25.17, 4.58};

    void validate() const;  // throws Error naming "--body" and the key
};

// "N[,seed=S][,female=F][,height_m=MEAN:SD][,height_f=MEAN:SD][,bmi_m=MEAN:SD][,bmi_f=MEAN:SD]" (cm, kg/m^2),
// the text after "population:". Unknown keys and values out of range are refused, naming "--body".
BodyPopulation parse_body_population(const std::string& text);

// The population's bodies, named "popNN_hHHH_mMM_s" (index, stature cm, mass kg, sex).
std::vector<BodySpec> sample_bodies(const BodyPopulation& population);

}  // namespace t2imu
