// .npz: round trips through libzip, a hand-built archive as another writer lays it out, and refusals.
#include <gtest/gtest.h>

#include <cstring>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "core/npz.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

uint32_t crc32_of(const std::vector<uint8_t>& b) {  // the zip (IEEE 802.3) CRC, bit by bit
    uint32_t c = 0xffffffffu;
    for (uint8_t byte : b) {
        c ^= byte;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

void put(std::vector<uint8_t>& out, uint64_t v, int bytes) {
    for (int k = 0; k < bytes; ++k) out.push_back(static_cast<uint8_t>(v >> (8 * k)));
}

// A zip of stored (uncompressed) members: local headers + data, central directory, end record.
std::vector<uint8_t> stored_zip(const std::vector<std::pair<std::string, std::vector<uint8_t>>>& members) {
    std::vector<uint8_t> out, central;
    for (const auto& [name, data] : members) {
        const size_t offset = out.size();
        const uint32_t crc = crc32_of(data);
        put(out, 0x04034b50, 4);
        put(out, 20, 2);
        put(out, 0, 2);
        put(out, 0, 2);  // signature, version, flags, stored
        put(out, 0, 4);
        put(out, crc, 4);
        put(out, data.size(), 4);
        put(out, data.size(), 4);  // time+date, crc, sizes
        put(out, name.size(), 2);
        put(out, 0, 2);
        out.insert(out.end(), name.begin(), name.end());
        out.insert(out.end(), data.begin(), data.end());
        put(central, 0x02014b50, 4);
        put(central, 20, 2);
        put(central, 20, 2);
        put(central, 0, 2);
        put(central, 0, 2);
        put(central, 0, 4);
        put(central, crc, 4);
        put(central, data.size(), 4);
        put(central, data.size(), 4);
        put(central, name.size(), 2);
        put(central, 0, 2);
        put(central, 0, 2);
        put(central, 0, 2);
        put(central, 0, 2);
        put(central, 0, 4);
        put(central, offset, 4);
        central.insert(central.end(), name.begin(), name.end());
    }
    const size_t cd_offset = out.size();
    out.insert(out.end(), central.begin(), central.end());
    put(out, 0x06054b50, 4);
    put(out, 0, 2);
    put(out, 0, 2);
    put(out, members.size(), 2);
    put(out, members.size(), 2);
    put(out, central.size(), 4);
    put(out, cd_offset, 4);
    put(out, 0, 2);
    return out;
}

std::string error_of(const std::vector<uint8_t>& bytes, const std::string& source) {
    try {
        parse_npz(bytes.data(), bytes.size(), source);
    } catch (const Error& e) {
        return e.what();
    }
    return "accepted";
}

}  // namespace

TEST(Npz, RoundTripStoredAndDeflated) {
    const std::string dir = test::scratch_dir("npz");
    std::map<std::string, NdArray> arrays = {
        {"v_template", NdArray::from(std::vector<double>(300, 0.25), {100, 3})},
        {"kintree_table", NdArray::from(std::vector<int64_t>{-1, 0, 0, 1}, {2, 2})},
        {"scalar", NdArray::from(std::vector<float>{2.5f}, {})},
        {"empty", NdArray::from(std::vector<uint8_t>{}, {0, 4})}};
    for (bool compress : {false, true}) {
        write_npz(dir + "/m.npz", arrays, compress);
        const std::vector<uint8_t> raw = read_file_bytes(dir + "/m.npz");
        // The first local header's compression method (bytes 8-9): 0 stored, 8 deflated.
        EXPECT_EQ(raw[8] | (raw[9] << 8), compress ? 8 : 0);
        const auto back = parse_npz(raw.data(), raw.size(), "m.npz");  // from memory
        ASSERT_EQ(back.size(), arrays.size());
        for (const auto& [name, a] : arrays) {
            EXPECT_EQ(back.at(name).dtype, a.dtype) << name;
            EXPECT_EQ(back.at(name).shape, a.shape) << name;
            EXPECT_EQ(back.at(name).bytes, a.bytes) << name;
        }
        EXPECT_EQ(read_npz(dir + "/m.npz").at("scalar").to<float>(), std::vector<float>{2.5f});
    }
    // Deflated: 300 equal doubles compress well below their 2400 bytes.
    EXPECT_LT(read_file_bytes(dir + "/m.npz").size(), 1500u);
}

TEST(Npz, ReadsAHandBuiltStoredArchive) {
    // Members as numpy.savez names them ("a.npy") and one without the suffix, which keeps its name.
    const auto a = serialize_npy(NdArray::from(std::vector<int32_t>{4, 5, 6}, {3}));
    const auto b = serialize_npy(NdArray::from(std::vector<double>{-1.5}, {1, 1}));
    const auto bytes = stored_zip({{"a.npy", a}, {"b", b}});
    const auto npz = parse_npz(bytes.data(), bytes.size(), "hand.npz");
    ASSERT_EQ(npz.size(), 2u);
    EXPECT_EQ(npz_member(npz, "a", "hand.npz").to<int32_t>(), (std::vector<int32_t>{4, 5, 6}));
    EXPECT_EQ(npz_member(npz, "b", "hand.npz").to<double>(), std::vector<double>{-1.5});
}

TEST(Npz, RefusesWhatIsNotAnNpz) {
    const std::vector<uint8_t> junk = {'P', 'K', 3, 4, 0, 0, 0};
    EXPECT_NE(error_of(junk, "junk.npz").find("junk.npz: zip: expected a zip archive"), std::string::npos);
    EXPECT_NE(error_of({}, "empty.npz").find("empty.npz: zip"), std::string::npos);
    const std::string dir = test::scratch_dir("npz_bad");
    write_npz(dir + "/ok.npz", {{"a", NdArray::from(std::vector<float>{1, 2}, {2})}});
    std::vector<uint8_t> bytes = read_file_bytes(dir + "/ok.npz");
    bytes.resize(bytes.size() / 2);
    EXPECT_THROW(parse_npz(bytes.data(), bytes.size(), "half.npz"), Error);
    EXPECT_THROW(read_npz(dir + "/missing.npz"), Error);
}

TEST(Npz, RefusesABadMemberNamingIt) {
    const std::string text = "not an array";
    const auto bytes = stored_zip({{"ok.npy", serialize_npy(NdArray::from(std::vector<float>{1}, {1}))},
                                   {"bad.npy", std::vector<uint8_t>(text.begin(), text.end())}});
    EXPECT_NE(error_of(bytes, "m.npz").find("m.npz:bad.npy: magic"), std::string::npos) << error_of(bytes, "m.npz");
    // "a" and "a.npy" would both be presented as "a".
    const auto a = serialize_npy(NdArray::from(std::vector<float>{1}, {1}));
    EXPECT_NE(error_of(stored_zip({{"a", a}, {"a.npy", a}}), "dup.npz").find("a twice"), std::string::npos);
}

TEST(Npz, MissingMemberIsNamed) {
    const auto bytes = stored_zip({{"betas.npy", serialize_npy(NdArray::from(std::vector<float>{1}, {1}))}});
    const auto npz = parse_npz(bytes.data(), bytes.size(), "body.npz");
    try {
        npz_member(npz, "shapedirs", "body.npz");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "body.npz: shapedirs: expected a member named 'shapedirs' (got only betas)");
    }
}

TEST(Npz, RefusesAMemberLargerThanTheArchiveCouldHold) {
    // Found by fuzz_npz: a 409-byte archive whose member header claims 2.6 GB; it must be refused before any
    // allocation of that size.
    const std::vector<uint8_t> bytes = read_file_bytes(test::source_dir() + "/tests/data/npz_forged_member_size.npz");
    ASSERT_LT(bytes.size(), 4096u);
    EXPECT_THROW(parse_npz(bytes.data(), bytes.size(), "forged.npz"), Error);
}
