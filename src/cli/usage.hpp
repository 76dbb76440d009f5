// Bad usage, told apart from failed work by its exit code: a value the options refuse before any work (a range,
// a non-finite number, an output path that cannot be made) exits 2 like a flag CLI11 refuses; anything that goes
// wrong while working (an unreadable input, a full disk) exits 1.
#pragma once
#include "core/error.hpp"

namespace t2imu::cli {

class UsageError : public Error {
public:
    explicit UsageError(const std::string& message) : Error(message) {}
};

// Runs the checks in `check` (options' validate(), check_output...) and turns their Error into UsageError.
template <class Check>
void check_usage(Check check) {
    try {
        check();
    } catch (const UsageError&) {
        throw;
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

}  // namespace t2imu::cli
