// libFuzzer target: parse_safetensors on arbitrary bytes.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "core/safetensors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const t2imu::SafeTensors st = t2imu::parse_safetensors(data, size, "fuzz.safetensors");
        for (const auto& [name, t] : st.tensors) (void)t.to<float>();
    } catch (const t2imu::Error&) {}
    return 0;
}
