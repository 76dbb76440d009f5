// Which bodies to synthesise for: a person's height, mass and sex, the paper's eight presets (Häusler et al.,
// Table 1), a user's SMPL file, or the input skeleton as it is.
#pragma once
#include <string>
#include <vector>

namespace t2imu {

enum class Sex { male, female };

struct BodySpec {
    enum class Kind { procedural, smpl, none };
    Kind kind = Kind::procedural;
    std::string name;        // folder name in outputs: "male_tall", "h172_m70_f", "smpl", "none"
    double height_m = 1.75;  // standing height, sole to vertex
    double mass_kg = 70.0;
    Sex sex = Sex::male;
    std::string smpl_path;      // Kind::smpl: the model .npz
    std::vector<double> betas;  // Kind::smpl: shape coefficients (missing ones are 0)
};

// The paper's Table 1: male/female tall, short, average, adipose.
const std::vector<BodySpec>& paper_bodies();

// One --body argument: "preset:NAME", "paper8", "height=172,mass=70,sex=f" (cm, kg), "smpl:FILE.npz[,betas=b0;b1;...]",
// "population:N[,...]" (N bodies drawn from anthropometric statistics, body_population.hpp) or "none". Several
// specs may be joined with '+'. Throws Error naming "--body" for anything else.
std::vector<BodySpec> parse_body_specs(const std::string& text);

const char* sex_name(Sex s);

// A number in a --body spec: the whole text, finite; throws Error naming "--body" and `field` otherwise.
double parse_body_number(const std::string& text, const std::string& field);

}  // namespace t2imu
