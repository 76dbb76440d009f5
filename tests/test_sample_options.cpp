// The sampler names and the sampling options' checks (diffusion/sample_options.hpp), without libtorch.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "diffusion/sample_options.hpp"
#include "test_util.hpp"

using namespace t2imu;

TEST(SampleOptions, SamplerNamesRoundTripAndOthersAreRefusedByOption) {
    for (Sampler s : {Sampler::ddpm, Sampler::ddim, Sampler::dpmpp}) EXPECT_EQ(parse_sampler(sampler_name(s)), s);
    EXPECT_EQ(sampler_names().size(), 3u);
    try {
        parse_sampler("euler", "synth.sampler");
        FAIL() << "euler accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("synth.sampler"), std::string::npos) << e.what();
    }
    EXPECT_EQ(denoiser_calls(Sampler::ddpm, 20, 1000), 1000);  // every step of the schedule
    EXPECT_EQ(denoiser_calls(Sampler::dpmpp, 20, 1000), 20);
}

TEST(SampleOptions, DefaultsPassAndEachBadValueIsRefusedByItsOption) {
    EXPECT_NO_THROW(SampleOptions{}.validate());
    const auto refusal = [](auto change) {
        SampleOptions o;
        change(o);
        return test::error_message([&] { o.validate(); });
    };
    EXPECT_NE(refusal([](SampleOptions& o) { o.frames = 197; }).find("--frames"), std::string::npos);
    EXPECT_NE(refusal([](SampleOptions& o) { o.frames = 3; }).find("--frames"), std::string::npos);
    EXPECT_NE(refusal([](SampleOptions& o) {
                  o.sampler = Sampler::dpmpp;
                  o.steps = 0;
              }).find("--steps"),
              std::string::npos);
    EXPECT_NE(refusal([](SampleOptions& o) { o.guidance = std::nan(""); }).find("--guidance"), std::string::npos);
    EXPECT_NE(refusal([](SampleOptions& o) { o.guidance = 1e20; }).find("--guidance"), std::string::npos);
    EXPECT_NE(refusal([](SampleOptions& o) { o.guidance = -1; }).find("--guidance"), std::string::npos);
    EXPECT_NE(refusal([](SampleOptions& o) { o.eta = 1.5; }).find("--eta"), std::string::npos);
    EXPECT_NE(refusal([](SampleOptions& o) { o.batch = 0; }).find("--batch"), std::string::npos);
    EXPECT_NE(refusal([](SampleOptions& o) { o.strength = 0; }).find("--strength"), std::string::npos);
    EXPECT_NE(refusal([](SampleOptions& o) {
                  o.start_motions = {FeatureMatrix::Zero(o.frames - 1, 263)};
              }).find("start motion"),
              std::string::npos);
    // DDPM takes every step of the schedule: its `steps` is not read, so not checked.
    SampleOptions ddpm;
    ddpm.sampler = Sampler::ddpm;
    ddpm.steps = 0;
    EXPECT_NO_THROW(ddpm.validate());
}

TEST(SampleOptions, SecondsBecomeFramesAt20FpsWithinTheSampledLengths) {
    EXPECT_EQ(frames_for_seconds(6.0, "--seconds"), 120);
    EXPECT_EQ(frames_for_seconds(0.2, "--seconds"), 4);
    EXPECT_EQ(frames_for_seconds(9.8, "--seconds"), 196);
    EXPECT_EQ(frames_for_seconds(1.26, "--seconds"), 25);  // rounded, as synth and sample always did
    for (const double bad : {0.1, 9.9, -1.0, 1e12, std::nan(""), HUGE_VAL}) {
        const std::string message = test::error_message([&] { frames_for_seconds(bad, "--seconds"); });
        EXPECT_EQ(message.rfind("--seconds", 0), 0u) << bad << ": " << message;
    }
}
