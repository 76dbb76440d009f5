// Procedural bodies: the paper's presets, anthropometric construction, skin points; body specs.
#include <gtest/gtest.h>

#include "body/body_population.hpp"
#include "body/body_spec.hpp"
#include "body/procedural_body.hpp"
#include "core/error.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;
using Eigen::Vector3d;

TEST(BodySpec, PaperEightMatchTable1) {
    const std::vector<BodySpec> b = parse_body_specs("paper8");
    ASSERT_EQ(b.size(), 8u);
    EXPECT_EQ(b[0].name, "male_tall");
    EXPECT_DOUBLE_EQ(b[0].height_m, 2.00);
    EXPECT_DOUBLE_EQ(b[3].mass_kg, 111);
    EXPECT_DOUBLE_EQ(b[6].height_m, 1.658);
    EXPECT_DOUBLE_EQ(b[6].mass_kg, 69.2);
    EXPECT_EQ(b[7].sex, Sex::female);
    for (const BodySpec& s : b) {  // the table's range: 150-200 cm, 50-111 kg
        EXPECT_GE(s.height_m, 1.50);
        EXPECT_LE(s.height_m, 2.00);
        EXPECT_GE(s.mass_kg, 50);
        EXPECT_LE(s.mass_kg, 111);
    }
}

TEST(BodySpec, ParsesMeasurementsPresetsAndRefusesNonsense) {
    const std::vector<BodySpec> b = parse_body_specs("height=172,mass=70,sex=f+preset:male_short+none");
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(b[0].name, "h172_m70_f");
    EXPECT_DOUBLE_EQ(b[0].height_m, 1.72);
    EXPECT_EQ(b[0].sex, Sex::female);
    EXPECT_EQ(b[1].name, "male_short");
    EXPECT_EQ(b[2].kind, BodySpec::Kind::none);
    const BodySpec smpl = parse_body_specs("smpl:/x/model.npz,betas=0.5;-1")[0];
    EXPECT_EQ(smpl.smpl_path, "/x/model.npz");
    EXPECT_EQ(smpl.betas, (std::vector<double>{0.5, -1}));
    for (const char* bad : {"preset:giant", "height=172,mass=70", "height=abc,mass=70,sex=m",
                            "height=900,mass=70,sex=m", "tall", "smpl:", "preset:male_tall+preset:male_tall"})
        EXPECT_THROW(parse_body_specs(bad), Error) << bad;
}

namespace {

struct Moments {
    double mean = 0, sd = 0;
};

Moments moments(const std::vector<double>& v) {
    Moments m;
    for (double x : v) m.mean += x / v.size();
    for (double x : v) m.sd += (x - m.mean) * (x - m.mean) / (v.size() - 1);
    m.sd = std::sqrt(m.sd);
    return m;
}

}  // namespace

TEST(BodyPopulation, DrawsHaveThePopulationsMomentsPerSex) {
    const BodyPopulation p;        // the defaults: the paper's averages, NCHS spreads
    std::vector<BodySpec> bodies;  // four seeds of the largest population: 4000 independent draws
    for (int seed = 7; seed < 11; ++seed) {
        const std::vector<BodySpec> drawn = parse_body_specs("population:1000,seed=" + std::to_string(seed));
        bodies.insert(bodies.end(), drawn.begin(), drawn.end());
    }
    for (Sex sex : {Sex::male, Sex::female}) {
        std::vector<double> height_cm, bmi;
        for (const BodySpec& b : bodies)
            if (b.sex == sex) {
                height_cm.push_back(b.height_m * 100);
                bmi.push_back(b.mass_kg / (b.height_m * b.height_m));
            }
        ASSERT_EQ(height_cm.size(), 2000u) << "female share 0.5, exactly";
        const MeanSd& h = sex == Sex::male ? p.height_cm_male : p.height_cm_female;
        const MeanSd& q = sex == Sex::male ? p.bmi_male : p.bmi_female;
        // Standard errors with n = 2000: mean sd/45, sd sd/63. Truncation at 3 sd shrinks a normal's sd by
        // sqrt(1 - 6 phi(3) / (2 Phi(3) - 1)) = 0.9866 and leaves a log-normal of this spread's mean within 0.05 %.
        const Moments hm = moments(height_cm), bm = moments(bmi);
        EXPECT_NEAR(hm.mean, h.mean, 4 * h.sd / 45) << sex_name(sex);
        EXPECT_NEAR(hm.sd, 0.9866 * h.sd, 4 * h.sd / 63) << sex_name(sex);
        EXPECT_NEAR(bm.mean, q.mean, 4 * q.sd / 45) << sex_name(sex);
        EXPECT_NEAR(bm.sd, q.sd, 0.06 * q.sd) << sex_name(sex);
        for (double x : height_cm) {
            EXPECT_LE(std::abs(x - h.mean), 3 * h.sd + 1e-9);
        }
    }
}

TEST(BodyPopulation, SeededPrefixStableAndExactSexShare) {
    const std::vector<BodySpec> eight = parse_body_specs("population:8,seed=3"),
                                four = parse_body_specs("population:4,seed=3");
    for (size_t i = 0; i < four.size(); ++i) {
        EXPECT_EQ(four[i].name, eight[i].name);
        EXPECT_DOUBLE_EQ(four[i].height_m, eight[i].height_m);
        EXPECT_DOUBLE_EQ(four[i].mass_kg, eight[i].mass_kg);
    }
    EXPECT_EQ(parse_body_specs("population:8")[5].mass_kg, parse_body_specs("population:8,seed=0")[5].mass_kg);
    EXPECT_NE(parse_body_specs("population:8,seed=4")[5].mass_kg, eight[5].mass_kg);
    const std::vector<BodySpec> ten = parse_body_specs("population:10,female=0.3,height_f=160:0,bmi_f=22:0");
    int women = 0;
    for (size_t i = 0; i < ten.size(); ++i)
        if (ten[i].sex == Sex::female) {
            ++women;
            EXPECT_DOUBLE_EQ(ten[i].height_m, 1.60);  // no spread: the mean itself
            EXPECT_NEAR(ten[i].mass_kg, 22 * 1.6 * 1.6, 1e-9);
            EXPECT_EQ(ten[i].name, "pop" + std::to_string(i) + "_h160_m56_f");
        }
    EXPECT_EQ(women, 3);
    EXPECT_EQ(parse_body_specs("population:11")[10].name.substr(0, 6), "pop10_");
    EXPECT_EQ(parse_body_specs("population:11")[0].name.substr(0, 6), "pop00_");
    for (const char* bad :
         {"population:0", "population:2.5", "population:", "population:3,female=2", "population:3,height_m=175",
          "population:3,height_m=175:30", "population:3,bmi_f=25:-1", "population:3,foo=1", "population:3,seed=-1",
          "population:1001", "population:3+population:3"})
        EXPECT_THROW(parse_body_specs(bad), Error) << bad;
}

TEST(ProceduralBody, PresetsHaveTheTablesHeightsAndMasses) {
    for (const BodySpec& spec : paper_bodies()) {
        const ProceduralBody body(spec);
        EXPECT_NEAR(body.vertex_height(), spec.height_m, 1e-12) << spec.name;
        double lowest = 1e9;
        for (const Vector3d& j : body.rest_joints()) lowest = std::min(lowest, j.y());
        EXPECT_GT(lowest, 0.0) << spec.name;  // every joint above the floor
        EXPECT_NEAR(body.rest_joints()[left_ankle].y(), 0.039 * spec.height_m, 1e-12);
        // The limb frusta hold de Leva's limb mass shares at the model's density (hands in the forearms):
        // male 2 x 24.80 %, female 2 x 25.37 % of 99.99 %.
        const double share = spec.sex == Sex::male ? 2 * 24.80 / 100.0 : 2 * 25.37 / 99.99;
        EXPECT_NEAR(body.limb_volume_m3() * ProceduralBody::kDensity, share * spec.mass_kg, 1e-9 * spec.mass_kg)
            << spec.name;
    }
}

TEST(ProceduralBody, HeavierBodyOfTheSameHeightIsThicker) {
    const ProceduralBody average(parse_body_specs("preset:male_average")[0]);
    const ProceduralBody adipose(parse_body_specs("preset:male_adipose")[0]);
    for (int s : {int(pelvis), int(spine2), int(left_hip), int(left_knee), int(left_shoulder)}) {
        // Same length, cross-section area scaled by the mass ratio 111 / 85.8 (limbs: mass share; trunk: BMI).
        EXPECT_DOUBLE_EQ(average.shape(s).length, adipose.shape(s).length);
        const double area_ratio = adipose.shape(s).half_width * adipose.shape(s).half_depth /
                                  (average.shape(s).half_width * average.shape(s).half_depth);
        EXPECT_NEAR(area_ratio, 111 / 85.8, 1e-12);
    }
    // Plausible sizes for an average man: mid-thigh circumference 45-62 cm, hip depth 20-30 cm.
    const SegmentShape& thigh = average.shape(left_hip);
    const double mid = (1 + thigh.taper) / 2, a = thigh.half_depth * mid, b = thigh.half_width * mid;
    const double circumference = M_PI * (3 * (a + b) - std::sqrt((3 * a + b) * (a + 3 * b)));  // Ramanujan
    EXPECT_GT(circumference, 0.45);
    EXPECT_LT(circumference, 0.62);
    EXPECT_GT(2 * average.shape(pelvis).half_depth, 0.20);
    EXPECT_LT(2 * average.shape(pelvis).half_depth, 0.30);
}

TEST(ProceduralBody, SkinPointsLieOnTheFrustumWithOutwardNormals) {
    const ProceduralBody body(parse_body_specs("preset:female_average")[0]);
    const SegmentShape& shin = body.shape(left_knee);
    // Front of the left shin halfway down: straight in front of the bone (+Z) by the half-depth there.
    const SurfacePoint front = body.surface_point(left_knee, 0.5, 0);
    const Vector3d mid = (body.rest_joints()[left_knee] + body.rest_joints()[left_ankle]) / 2;
    const double scale = 1 + (shin.taper - 1) * 0.5;
    EXPECT_LT((front.position - (mid + Vector3d(0, 0, shin.half_depth * scale))).norm(), 1e-12);
    EXPECT_LT((front.normal - Vector3d::UnitZ()).norm(), 1e-12);
    // Lateral side of the left thigh: +X (the body's left); of the right thigh at -90 degrees: -X.
    EXPECT_LT((body.surface_point(left_hip, 0.4, M_PI / 2).normal - Vector3d::UnitX()).norm(), 1e-12);
    EXPECT_LT((body.surface_point(right_hip, 0.4, -M_PI / 2).normal + Vector3d::UnitX()).norm(), 1e-12);
    // An oblique point of an elliptic section: the normal is the ellipse's gradient, not the radial direction.
    const SurfacePoint oblique = body.surface_point(spine2, 0.5, M_PI / 4);
    const SegmentShape& s = body.shape(spine2);
    const double scale2 = 1 + (s.taper - 1) * 0.5;
    const double a = s.half_depth * scale2, b = s.half_width * scale2;
    const Vector3d expected_normal = Vector3d(std::sqrt(0.5) / b, 0, std::sqrt(0.5) / a).normalized();
    EXPECT_LT((oblique.normal - expected_normal).norm(), 1e-12);
    EXPECT_THROW(body.vertex_point(3), Error);
}

TEST(ProceduralBody, SexChangesBreadthsNotStature) {
    BodySpec m = parse_body_specs("height=170,mass=65,sex=m")[0], f = parse_body_specs("height=170,mass=65,sex=f")[0];
    const ProceduralBody male(m), female(f);
    EXPECT_DOUBLE_EQ(male.vertex_height(), female.vertex_height());
    const auto width = [](const ProceduralBody& b, int l, int r) {
        return (b.rest_joints()[l] - b.rest_joints()[r]).norm();
    };
    EXPECT_GT(width(female, left_hip, right_hip), width(male, left_hip, right_hip));
    EXPECT_LT(width(female, left_shoulder, right_shoulder), width(male, left_shoulder, right_shoulder));
}
