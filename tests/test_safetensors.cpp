#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "core/error.hpp"
#include "core/safetensors.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

std::vector<uint8_t> file_with(const std::string& header, size_t data_bytes) {
    std::vector<uint8_t> out(8 + header.size() + data_bytes, 0);
    for (size_t k = 0; k < 8; ++k) out[k] = static_cast<uint8_t>((header.size() >> (8 * k)) & 0xff);
    std::copy(header.begin(), header.end(), out.begin() + 8);
    return out;
}

}  // namespace

TEST(SafeTensors, RoundTripWithMetadataAndNameOrder) {
    SafeTensors st;
    st.metadata["format"] = "pt";
    st.tensors["b.weight"] = NdArray::from(std::vector<float>{1, 2, 3, 4, 5, 6}, {2, 3});
    st.tensors["a.bias"] = NdArray::from(std::vector<int64_t>{7}, {1});
    NdArray bf;
    bf.dtype = DType::bf16;
    bf.shape = {2};
    bf.bytes = {0x80, 0x3f, 0x00, 0xc0};  // 1.0, -2.0
    st.tensors["c.half"] = bf;
    const std::vector<uint8_t> bytes = serialize_safetensors(st);
    uint64_t n = 0;
    for (int k = 7; k >= 0; --k) n = (n << 8) | bytes[static_cast<size_t>(k)];
    EXPECT_EQ(n % 8, 0u);
    const std::string header(bytes.begin() + 8, bytes.begin() + 8 + static_cast<long>(n));
    EXPECT_LT(header.find("a.bias"), header.find("b.weight"));  // data in name order
    const SafeTensors back = parse_safetensors(bytes.data(), bytes.size(), "m.safetensors");
    EXPECT_EQ(back.metadata.at("format"), "pt");
    EXPECT_EQ(back.tensors.at("b.weight").to<float>(), (std::vector<float>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(back.tensors.at("c.half").to<float>(), (std::vector<float>{1.0f, -2.0f}));
    const std::string dir = test::scratch_dir("safetensors");
    write_safetensors(dir + "/m.safetensors", st);
    EXPECT_EQ(read_safetensors(dir + "/m.safetensors").tensors.at("a.bias").to<int64_t>(), (std::vector<int64_t>{7}));
}

TEST(SafeTensors, RefusesEveryMalformedLayout) {
    struct Case {
        std::string header;
        size_t data;
        const char* field;
    };
    const Case cases[] = {
        {R"({"w":{"dtype":"F32","shape":[2],"data_offsets":[0,8]}})", 4, "w.data_offsets"},  // out of range
        {R"({"w":{"dtype":"F32","shape":[3],"data_offsets":[0,8]}})", 8, "w.data_offsets"},  // size mismatch
        {R"({"w":{"dtype":"F32","shape":[2],"data_offsets":[0,8]},"v":{"dtype":"F32","shape":[2],"data_offsets":[4,12]}})",
         12, "v.data_offsets"},                                                              // overlap
        {R"({"w":{"dtype":"F32","shape":[1],"data_offsets":[4,8]}})", 8, "w.data_offsets"},  // gap
        {R"({"w":{"dtype":"F32","shape":[1],"data_offsets":[0,4]}})", 8, "data"},            // trailing bytes
        {R"({"w":{"dtype":"C64","shape":[1],"data_offsets":[0,8]}})", 8, "w.dtype"},
        {R"({"w":{"dtype":"F32","shape":[-1],"data_offsets":[0,4]}})", 4, "w.shape"},
        {R"({"w":{"dtype":"F32","shape":[1]}})", 4, "w"},
        {R"({"w":{"dtype":"F32","shape":[0,4000000000000,4000000000000],"data_offsets":[0,0]}})", 0, "w.shape"},
        {R"({"__metadata__":{"k":1}})", 0, "__metadata__.k"},
        {R"({"w": )", 0, "header"},
    };
    for (const Case& c : cases) {
        const auto bytes = file_with(c.header, c.data);
        try {
            parse_safetensors(bytes.data(), bytes.size(), "bad.safetensors");
            ADD_FAILURE() << "accepted " << c.header;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("bad.safetensors: ") + c.field), std::string::npos)
                << e.what();
        }
    }
    std::vector<uint8_t> huge = file_with("{}", 0);
    huge[6] = 1;  // header length 2^48
    EXPECT_THROW(parse_safetensors(huge.data(), huge.size(), "huge"), Error);
}
