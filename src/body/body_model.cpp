#include "body/body_model.hpp"

#include "body/procedural_body.hpp"
#include "body/smpl_model.hpp"
#include "core/error.hpp"

namespace t2imu {

std::unique_ptr<BodyModel> make_body(const BodySpec& spec) {
    switch (spec.kind) {
        case BodySpec::Kind::procedural: return std::make_unique<ProceduralBody>(spec);
        case BodySpec::Kind::smpl: return std::make_unique<SmplBody>(spec);
        case BodySpec::Kind::none: break;
    }
    throw Error("--body", "none", "a body the caller sizes to the input motion (size_none_body)");
}

}  // namespace t2imu
