#include "body/body_spec.hpp"

#include <cmath>
#include <sstream>

#include "body/body_population.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

const std::vector<BodySpec>& paper_bodies() {
    static const std::vector<BodySpec> bodies = [] {
        struct Row {
            const char* name;
            double cm, kg;
            Sex sex;
        };
        const Row rows[] = {
            {"male_tall", 200, 100, Sex::male},           {"male_short", 160, 60, Sex::male},
            {"male_average", 178.9, 85.8, Sex::male},     {"male_adipose", 178.9, 111, Sex::male},
            {"female_tall", 180, 75, Sex::female},        {"female_short", 150, 50, Sex::female},
            {"female_average", 165.8, 69.2, Sex::female}, {"female_adipose", 165.8, 97, Sex::female},
        };
        std::vector<BodySpec> out;
        for (const Row& r : rows) {
            BodySpec b;
            b.name = r.name;
            b.height_m = r.cm / 100.0;
            b.mass_kg = r.kg;
            b.sex = r.sex;
            out.push_back(b);
        }
        return out;
    }();
    return bodies;
}

const char* sex_name(Sex s) { return s == Sex::male ? "male" : "female"; }

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> parts;
    std::stringstream in(s);
    for (std::string part; std::getline(in, part, sep);) parts.push_back(part);
    return parts;
}

}  // namespace

double parse_body_number(const std::string& text, const std::string& field) {
    return finite_number(text, "--body", field);
}

namespace {

BodySpec parse_measurements(const std::string& text) {
    BodySpec b;
    bool have_height = false, have_mass = false, have_sex = false;
    for (const std::string& kv : split(text, ',')) {
        const size_t eq = kv.find('=');
        const std::string key = kv.substr(0, eq), value = eq == std::string::npos ? "" : kv.substr(eq + 1);
        if (key == "height") {
            b.height_m = parse_body_number(value, "height") / 100.0;
            have_height = true;
        } else if (key == "mass") {
            b.mass_kg = parse_body_number(value, "mass");
            have_mass = true;
        } else if (key == "sex" && (value == "m" || value == "male" || value == "f" || value == "female")) {
            b.sex = value[0] == 'm' ? Sex::male : Sex::female;
            have_sex = true;
        } else {
            throw Error("--body", kv, "height=CM, mass=KG or sex=m|f");
        }
    }
    if (!have_height || !have_mass || !have_sex) throw Error("--body", text, "height=CM,mass=KG,sex=m|f (all three)");
    if (b.height_m < 0.5 || b.height_m > 2.5)
        throw Error("--body", "height", "50 to 250 cm", std::to_string(b.height_m * 100));
    if (b.mass_kg < 10 || b.mass_kg > 300) throw Error("--body", "mass", "10 to 300 kg", std::to_string(b.mass_kg));
    std::ostringstream name;
    name << "h" << std::lround(b.height_m * 100) << "_m" << std::lround(b.mass_kg) << "_"
         << (b.sex == Sex::male ? "m" : "f");
    b.name = name.str();
    return b;
}

BodySpec parse_smpl(const std::string& text) {
    BodySpec b;
    b.kind = BodySpec::Kind::smpl;
    b.name = "smpl";
    const std::vector<std::string> parts = split(text, ',');
    if (parts.empty() || parts[0].empty()) throw Error("--body", "smpl", "smpl:FILE.npz[,betas=b0;b1;...]", text);
    b.smpl_path = parts[0];
    for (size_t i = 1; i < parts.size(); ++i) {
        if (parts[i].rfind("betas=", 0) != 0) throw Error("--body", parts[i], "betas=b0;b1;...");
        for (const std::string& v : split(parts[i].substr(6), ';')) b.betas.push_back(parse_body_number(v, "betas"));
    }
    return b;
}

void append_one(const std::string& text, std::vector<BodySpec>& out) {
    if (text == "paper8") {
        out.insert(out.end(), paper_bodies().begin(), paper_bodies().end());
    } else if (text == "none") {
        BodySpec b;
        b.kind = BodySpec::Kind::none;
        b.name = "none";
        out.push_back(b);
    } else if (text.rfind("preset:", 0) == 0) {
        const std::string name = text.substr(7);
        for (const BodySpec& b : paper_bodies())
            if (b.name == name) return out.push_back(b);
        std::string names;
        for (const BodySpec& b : paper_bodies()) names += (names.empty() ? "" : ", ") + b.name;
        throw Error("--body", "preset", "one of " + names, name);
    } else if (text.rfind("population:", 0) == 0) {
        const std::vector<BodySpec> drawn = sample_bodies(parse_body_population(text.substr(11)));
        out.insert(out.end(), drawn.begin(), drawn.end());
    } else if (text.rfind("smpl:", 0) == 0) {
        out.push_back(parse_smpl(text.substr(5)));
    } else if (text.find('=') != std::string::npos) {
        out.push_back(parse_measurements(text));
    } else {
        throw Error("--body", "spec",
                    "preset:NAME, paper8, population:N, height=CM,mass=KG,sex=m|f, smpl:FILE.npz or none", text);
    }
}

}  // namespace

std::vector<BodySpec> parse_body_specs(const std::string& text) {
    std::vector<BodySpec> out;
    for (const std::string& one : split(text, '+')) append_one(one, out);
    if (out.empty()) throw Error("--body", "spec", "at least one body", text);
    for (size_t i = 0; i < out.size(); ++i)
        for (size_t k = 0; k < i; ++k)
            if (out[i].name == out[k].name)
                throw Error("--body", "spec", "distinct bodies", "two named " + out[i].name);
    return out;
}

}  // namespace t2imu
