#include "pipeline/motion_source_spec.hpp"

#include <optional>

#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

MotionSourceSpec parse_motion_source(const std::string& spelling) {
    const std::string retrieval = "retrieval:", hybrid = "hybrid:";
    if (spelling.empty()) throw Error("--model", "source", "a model folder, retrieval:DATASET or hybrid:...", "");
    if (spelling.rfind(retrieval, 0) == 0) return RetrievalSpec{spelling.substr(retrieval.size())};
    if (spelling.rfind(hybrid, 0) != 0) return ModelFolderSpec{spelling};
    const std::string rest = spelling.substr(hybrid.size());
    const size_t a = rest.find(','), b = a == std::string::npos ? a : rest.find(',', a + 1);
    const std::string expected = "hybrid:MODEL_FOLDER,DATASET,STRENGTH with STRENGTH above 0 and at most 1";
    if (b == std::string::npos || rest.find(',', b + 1) != std::string::npos)
        throw Error("--model", "hybrid", expected, spelling);
    const std::optional<double> strength = parse_number(rest.substr(b + 1));
    if (!strength || !(*strength > 0 && *strength <= 1))
        throw Error("--model", "hybrid strength", expected, rest.substr(b + 1));
    return HybridSpec{rest.substr(0, a), rest.substr(a + 1, b - a - 1), *strength};
}

}  // namespace t2imu
