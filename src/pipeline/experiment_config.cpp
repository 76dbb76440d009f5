// experiments/*.toml -> ExperimentConfig (pipeline/experiment.hpp). Paths are taken as written: relative ones
// resolve against the working directory, the repository root for the shipped configs.
#include <set>

#include "core/error.hpp"
#include "core/toml_section.hpp"
#include "pipeline/experiment.hpp"
#include "pipeline/synth_keys.hpp"

namespace t2imu {

namespace {

// Reads one shared setting (pipeline/synth_keys.hpp) of an experiment's [synth]; plan_synth checks the values.
struct ReadSynthKey {
    TomlSection& section;
    const std::string& path;
    template <class T>
    void operator()(SynthKey<T> k) const {
        section.read(k.key, k.field);
    }
    void operator()(SynthKey<std::optional<double>> k) const {
        if (!section.has(k.key)) return;  // absent: unset
        double v = 0;
        section.read(k.key, v);
        k.field = v;
    }
    void operator()(SynthKey<Sampler> k) const {
        std::string name = sampler_name(k.field);
        section.read(k.key, name);
        k.field = parse_sampler(name, path + ": synth." + k.key);
    }
};

void read_synth(TomlSection s, SynthOptions& o, const std::string& path) {
    visit_synth_keys(o, ReadSynthKey{s, path});
    s.refuse_unknown_keys();
}

void read_har(TomlSection s, HarOptions& h, WindowOptions& w) {
    s.read("repeats", h.repeats);
    s.read("seed", h.seed);
    s.read("max_epochs", h.max_epochs);
    s.read("patience", h.patience);
    s.read("batch", h.batch);
    s.read("learning_rate", h.learning_rate);
    s.read("rate_hz", w.rate_hz);
    s.read("window_s", w.window_s);
    s.read("overlap", w.overlap);
    s.read("gyro", w.gyro);
    s.refuse_unknown_keys();
}

void read_lacc(TomlSection s, ExperimentLacc& l) {
    s.read("before", l.before);
    s.read("after", l.after);
    s.read("dataset", l.dataset);
    s.read("split", l.split);
    s.read("vocab", l.vocab);
    s.read("seed", l.seed);
    s.read("tau", l.tau);
    s.refuse_unknown_keys();
}

void check_names(const ExperimentConfig& c, const std::string& path) {
    std::set<std::string> sources, sets;
    for (const ExperimentSource& s : c.sources)
        if (s.name.empty() || s.name.find_first_of("/ -") != std::string::npos || !sources.insert(s.name).second)
            throw Error(path, "source.name", "unique names without '/', ' ' or '-'", s.name);
    for (const ExperimentRealSet& r : c.real_sets)
        if (r.name.empty() || r.name.find_first_of("/ -") != std::string::npos || !sets.insert(r.name).second ||
            r.name == "real")
            throw Error(path, "real.name", "unique names without '/', ' ' or '-', other than 'real'", r.name);
    if (c.sources.empty() || c.real_sets.empty())
        throw Error(path, "source, real", "at least one [[source]] and one [[real]]");
    for (const std::string& name : {c.lacc.before, c.lacc.after})
        if (!name.empty() && !sources.count(name)) throw Error(path, "lacc", "before/after naming a [[source]]", name);
    if (c.lacc.before.empty() != c.lacc.after.empty()) throw Error(path, "lacc", "both before and after, or neither");
}

}  // namespace

ExperimentConfig read_experiment_config(const std::string& path) {
    const toml::table doc = parse_toml_file(path);
    TomlSection top(doc, path, "");
    ExperimentConfig c;
    c.path = path;
    read_synth(top.table("synth"), c.synth, path);
    for (TomlSection s : top.array_of_tables("source")) {
        ExperimentSource src;
        s.require("name", src.name);
        s.require("model", src.model);
        s.refuse_unknown_keys();
        c.sources.push_back(src);
    }
    for (TomlSection s : top.array_of_tables("real")) {
        ExperimentRealSet r;
        s.require("name", r.name);
        s.require("dataset", r.dataset);
        s.require("prompts", r.prompts);
        s.require("sensors", r.sensors);
        s.read("realism", r.realism);  // parsed with the row's synthesis plan (plan_experiment)
        s.read("positions", r.positions);
        s.read("ceiling_folds", r.ceiling_folds);
        s.refuse_unknown_keys();
        c.real_sets.push_back(r);
    }
    read_har(top.table("har"), c.har, c.windows);
    // Checked now, not when the first training starts after the syntheses (the messages name the options).
    try {
        c.har.validate();
        c.windows.validate();
    } catch (const Error& e) {
        throw Error(path, "har", "valid HAR settings", e.what());
    }
    TomlSection features = top.table("features");
    features.read("tsne_points", c.tsne_points);
    features.read("perplexity", c.tsne.perplexity);
    features.read("seed", c.feature_seed);
    features.refuse_unknown_keys();
    read_lacc(top.table("lacc"), c.lacc);
    c.low_data = read_experiment_low_data(top.table("low_data"), path);
    top.refuse_unknown_keys();
    check_names(c, path);
    return c;
}

}  // namespace t2imu
