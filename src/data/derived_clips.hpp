// Motions derived from captured ones where open motion capture has (almost) none: stairs from captured level
// walks (motion/stair_gait.hpp), sitting down, sitting and standing up from captured idle standing
// (motion/sit_to_stand.hpp), and lying still, breathing, from the end of captured lie-down clips
// (motion/lying_still.hpp) and turning onto the side and back (motion/lying_turn.hpp), and jumps of another
// height from captured jumps (motion/jump_rescale.hpp). Each derived clip says what it is: method, source file,
// parameters and seed; the dataset builder tags it as source_dataset "edited" with the source clip's licence.
//
// Which captured recordings give which clips (only single-activity recordings, so the edit starts from what it
// assumes):
//   walking   one staircase clip, ascent or descent by the seed's parity (about half each). Rise uniform in
//             [0.15, 0.19] m and going in [0.25, 0.32] m (domestic and public stairs, see stair_gait.hpp); the
//             cadence factor and trunk lean within +-0.05 and +-0.03 rad of the direction's defaults. Walks
//             that the edit refuses (under 1.5 m of travel, backward or sideways, turning, fewer than four
//             footholds) give nothing. On request (stairs_round_trips), every other walk (by a bit of its seed)
//             also gives one round trip, up a flight and down the next (gait_splice.hpp: the two flights, on
//             stairs of one rise and going, joined at a stance of one foot on the landing), cut to a length
//             uniform in [kRoundTripMinSeconds, kRoundTripMaxSeconds] around the join (a 6 s prompt, the main
//             job's length, then has round trips of its length to follow); tag stairs (either direction).
//             On request (turning_walks), every walk also gives one turned onto a curve (walk_turn.hpp): by the
//             seed, two in three turn 60-120 deg over 1.2-2.2 s and one in three turns around, 150-180 deg over
//             1.5-2.5 s, left or right by a bit of the seed, starting at least 0.8 s into the walk and ending
//             0.8 s before its end; tag walking.
//   standing  up to kSitsPerRecording sit-down/stand-up clips, from windows spread evenly over the recording:
//             seat height uniform in [0.47, 0.57] x the standing hip-joint height (0.40-0.50 m for an adult's
//             0.88 m: ordinary chairs; ReActIdle's rigs stand 0.66-0.95 m at the hip), sitting down 1.8-2.4 s and
//             standing up 1.5-2.0 s (self-paced, sit_to_stand.hpp) times a pace factor uniform in
//             [kSitPaceFactorMin, kSitPaceFactorMax], seated 1-3 s, 0.3-1.0 s of standing before and after (the
//             three still phases shrunk in proportion where a slow pace leaves less room: at most 9.4 s, one
//             training clip), peak trunk flexion 0.55-0.85 rad. Windows where the idle stand steps away are
//             refused (sit_to_stand.hpp's kMaxStandingDriftM).
//             The pace spans what the real data sets show at the waist (signal_statistics' mag_rise / mag_dip,
//             m/s², medians): UMAFall's self-paced trials 3.05 / 1.98, SisFall's D07/D09, done "slowly" by
//             protocol, 2.04 / 0.98; the durations above alone (factor 1) gave 2.85 / 2.28 through SisFall's
//             device model, and 1.3 times them matched SisFall's. Captions do not name the pace (GloVe sentence
//             vectors put "quickly" next to "slowly": pace-worded captions drew slow clips for "quickly" prompts).
//   lying     kLyingPerRecording clips of the final pose held, breathing: 6-9.4 s long, 12-20 breaths/min
//             (quiet breathing at rest), peak rib-cage turn 0.015-0.025 rad. HDM05's lie-down clips reach the
//             floor seconds before they end; a HAR "lying" recording is mostly lying still. On request
//             (lying_turns), kLyingTurnsPerRecording clips of that pose, breathing, turning onto the side and back
//             (lying_turn.hpp), onto the left side in one and the right in the other: 70-90 deg (1.2-1.6 rad),
//             turns of 0.8-1.4 s each way, 1.5-2.4 s on the side, 0.5-1.2 s on the back before and after (at
//             most 7.6 s). The turns' pace is SisFall's (D14, on the back, onto the side and back in 12 s; waist
//             |a| sd 0.86 m/s², mag_rise 1.98): on SisFall's lying prompts, turns of 1.2-2.2 s gave 0.42 and
//             0.73, these 0.74 and 1.37. On request (lie_down_rests), one clip of the captured lie-down followed
//             by its final pose held, breathing, for 2-4 s (at most 9.5 s in all), with captions of lying down.
//   jumping   one clip of the jump rescaled, lower or higher by the seed's parity: time scale k uniform in
//             [0.88, 0.95] or [1.05, 1.12], so flights 0.77-0.90 or 1.10-1.25 times as high: within the spread of
//             jump heights between healthy adults, which is wider. A jump too short to train on (under 2 s) also
//             gives kJumpsPerSeriesMin-Max of itself in a row (jump_series.hpp), each rescaled with k uniform in
//             [0.9, 1.1]: a HAR data set's jumping is jumping over and over.
// Every edit runs at the rate of the recording it is given (the builder gives the capture rate where that is over
// 20 fps, so a derived clip keeps the texture the capture has: Bandai Namco walks 30 fps, ReActIdle 24, HDM05 60).
// A clip is kept only when it passes motion_quality's default thresholds at 20 fps (the dataset's rate, what the
// models see), measured by score_motion above the ground the clip's own footholds show (support_ground.hpp), as for
// generated motion.
// Each recording's seed is a hash of its file name, so a build gives the same clips every time.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

constexpr int kSitsPerRecording = 6;
// The pace of sitting down and standing up: a factor on both movements' durations, drawn per clip (uniform) from
// the self-paced trials of UMAFall to SisFall's slow ones (header above).
constexpr double kSitPaceFactorMin = 0.9;
constexpr double kSitPaceFactorMax = 1.45;
// A stairs round trip (up a flight, down the next) is cut to a length in this range around its splice: at most
// under the 10 s (199 frames at 20 fps) that MDM's data rules keep, at least long enough for two steps each way.
constexpr double kRoundTripMinSeconds = 5.5;
constexpr double kRoundTripMaxSeconds = 9.5;
constexpr int kLyingPerRecording = 2;
constexpr int kLyingTurnsPerRecording = 2;
// A lie-down followed by rest (lie_down_rests): the capture, then its final pose held for a uniform 2-4 s, the
// whole at most 9.5 s (under the 10 s that MDM's data rules keep); a capture that leaves under 2 s gives none.
constexpr double kLieDownRestMinSeconds = 2.0;
constexpr double kLieDownRestMaxSeconds = 4.0;
constexpr double kLieDownRestMaxClipSeconds = 9.5;
// Jumps in the series made from a single jump that is too short to train on (jump_series.hpp): 0.5-0.8 s each
// after rescaling, so at least 2.1 s (the training's 2 s minimum) and at most 6 s in all.
constexpr int kJumpsPerSeriesMin = 5;
constexpr int kJumpsPerSeriesMax = 8;

struct DerivedClip {
    // "stairs_up", "stairs_down", "stairs_round_trip", "sit_down_stand_up", "lying_still", "lying_turn",
    // "lie_down_rest", "jump_rescaled", "jump_series", "walk_turn"
    std::string method;
    std::string
        activity;  // its activity tag: stairs_up, stairs_down, stairs (a round trip), sitting, lying, jumping, walking
    JointSequence joints;        // at the source recording's rate, floor at y = 0 under the lowest joint
    JointSequence joints_20fps;  // the same at 20 fps (Catmull-Rom), as quality-scored and as the dataset holds it
    nlohmann::json parameters;   // the edit's options
    uint64_t seed = 0;
    std::vector<std::string> captions;  // three sentences for the whole clip
};

struct DeriveReport {
    int refused = 0;         // edits the source could not take (a turning walk, a short recording, no lying end)
    int failed_quality = 0;  // derived clips that failed the quality thresholds
};

// The derived clips of one captured recording (at any rate of at least 20 fps) whose activity tags are `tags`
// (the mocap manifest's, ';' between several). `file` seeds the draw. Counts what was left out in `report`.
// The clip kinds that are off by default, each for a measured reason.
struct DeriveOptions {
    // The turning clips of a lie-down: retrieval's HAR stayed within its spread and lying windows grew easier to
    // tell from real (docs/realism.md on lying turns); the learned default did not learn to turn from them.
    bool lying_turns = false;
    // The stairs round trips: fine-tuned on them, the learned default drew "up and back down" prompts as stairs but
    // every "down the stairs" prompt as going up, and no jumps
    // (docs/results.md on stairs round trips and lying turns).
    bool stairs_round_trips = false;
    // The lie-down and then rest (one per lie-down recording, captions of lying down): fine-tuned on them, the learned
    // model lies down for SisFall's lying prompts; stairs down and jumping go with the fine-tuning seed, with or
    // without them (docs/results.md on lie-down-and-rest clips). models/default is fine-tuned on a
    // build with them (experiments/default.toml).
    bool lie_down_rests = false;
    // Walks turned onto a curve (motion/walk_turn.hpp), one per captured walk: the captured walks turn less than 45
    // degrees, so a turn asked for in a prompt had no motion to learn from (docs/attributes.md).
    bool turning_walks = false;
};
std::vector<DerivedClip> derive_clips(const JointSequence& captured, const std::string& tags, const std::string& file,
                                      DeriveReport& report, const DeriveOptions& options = {});

}  // namespace t2imu
