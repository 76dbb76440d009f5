// .npy against hand-built byte layouts, NumPy-written files and malformed inputs.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

// A version-1.0 .npy with the given header dict and raw data bytes, laid out as NumPy does.
std::vector<uint8_t> npy_bytes(const std::string& dict, const std::vector<uint8_t>& data, int major = 1) {
    const size_t prefix = major == 1 ? 10 : 12;
    std::string h = dict;
    const size_t total = prefix + h.size() + 1;
    h.append((64 - total % 64) % 64, ' ');
    h += '\n';
    std::vector<uint8_t> out = {0x93, 'N', 'U', 'M', 'P', 'Y', static_cast<uint8_t>(major), 0};
    for (size_t k = 0; k < prefix - 8; ++k) out.push_back(static_cast<uint8_t>((h.size() >> (8 * k)) & 0xff));
    out.insert(out.end(), h.begin(), h.end());
    out.insert(out.end(), data.begin(), data.end());
    return out;
}

std::vector<uint8_t> floats(std::initializer_list<float> v) {
    std::vector<uint8_t> b(v.size() * 4);
    std::memcpy(b.data(), v.begin(), b.size());
    return b;
}

}  // namespace

TEST(Npy, ReadsHandBuiltVersions1To3) {
    for (int major : {1, 2, 3}) {
        const auto bytes =
            npy_bytes("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }", floats({1, 2, 3, 4, 5, 6}), major);
        const NdArray a = parse_npy(bytes.data(), bytes.size(), "v.npy");
        EXPECT_EQ(a.dtype, DType::f32);
        EXPECT_EQ(a.shape, (std::vector<int64_t>{2, 3}));
        EXPECT_EQ(a.to<float>(), (std::vector<float>{1, 2, 3, 4, 5, 6}));
    }
}

TEST(Npy, FortranOrderIsReadIntoCOrder) {
    // np.asfortranarray([[1, 2, 3], [4, 5, 6]]) stores the columns one after the other: 1 4 2 5 3 6.
    const auto bytes =
        npy_bytes("{'descr': '<f4', 'fortran_order': True, 'shape': (2, 3), }", floats({1, 4, 2, 5, 3, 6}));
    const NdArray a = parse_npy(bytes.data(), bytes.size(), "f.npy");
    EXPECT_EQ(a.shape, (std::vector<int64_t>{2, 3}));
    EXPECT_EQ(a.to<float>(), (std::vector<float>{1, 2, 3, 4, 5, 6}));
}

TEST(Npy, ZeroDimensionalAndEmptyArrays) {
    const auto scalar =
        npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (), }", std::vector<uint8_t>(8, 0));
    EXPECT_EQ(parse_npy(scalar.data(), scalar.size(), "s.npy").size(), 1);
    const auto empty = npy_bytes("{'descr': '<i8', 'fortran_order': False, 'shape': (0, 5), }", {});
    EXPECT_EQ(parse_npy(empty.data(), empty.size(), "e.npy").size(), 0);
}

TEST(Npy, WriterLayoutMatchesNumPy) {
    // NumPy 1.24 writes exactly these 128 header bytes for np.save(f, np.zeros((2,3), np.float32)).
    const NdArray a = NdArray::from(std::vector<float>(6, 0.f), {2, 3});
    const std::vector<uint8_t> b = serialize_npy(a);
    ASSERT_EQ(b.size(), 128u + 24u);
    const std::string header(b.begin() + 10, b.begin() + 128);
    EXPECT_EQ(header.rfind("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }", 0), 0u);
    EXPECT_EQ(header.back(), '\n');
    EXPECT_EQ(b[8] | (b[9] << 8), 118);
}

TEST(Npy, RoundTripsEveryDtype) {
    const std::string dir = test::scratch_dir("npy_roundtrip");
    std::vector<NdArray> arrays = {
        NdArray::from(std::vector<double>{1.5, -2.25}, {2}), NdArray::from(std::vector<int32_t>{-7, 8, 9}, {3, 1}),
        NdArray::from(std::vector<int64_t>{1ll << 40}, {1}), NdArray::from(std::vector<uint8_t>{0, 255}, {2}),
        NdArray::from(std::vector<bool>{true, false, true}, {3})};
    NdArray half;
    half.dtype = DType::f16;
    half.shape = {2};
    half.bytes = {0x00, 0x3c, 0x00, 0xc0};  // 1.0, -2.0
    arrays.push_back(half);
    for (const NdArray& a : arrays) {
        write_npy(dir + "/a.npy", a);
        const NdArray b = read_npy(dir + "/a.npy");
        EXPECT_EQ(b.dtype, a.dtype);
        EXPECT_EQ(b.shape, a.shape);
        EXPECT_EQ(b.bytes, a.bytes);
    }
    EXPECT_EQ(read_npy(dir + "/a.npy").to<float>(), (std::vector<float>{1.0f, -2.0f}));
}

TEST(Npy, ReadsNumPyWrittenFiles) {
    std::string vecs;
    SHARED_OR_SKIP(vecs, "reference/humanml3d/repo_files/HumanML3D/new_joint_vecs/012314.npy");
    const NdArray a = read_npy(vecs);
    EXPECT_EQ(a.dtype, DType::f32);
    EXPECT_EQ(a.shape, (std::vector<int64_t>{170, 263}));
    const NdArray j = read_npy(test::shared_path("reference/humanml3d/generated/seq_000021_raw/input_joints.npy"));
    EXPECT_EQ(j.dtype, DType::f64);
    EXPECT_EQ(j.shape, (std::vector<int64_t>{180, 22, 3}));
}

TEST(Npy, RefusesMalformedInputNamingTheField) {
    const std::vector<uint8_t> six = floats({1, 2, 3, 4, 5, 6});
    struct Case {
        std::string dict;
        std::vector<uint8_t> data;
        const char* field;
    };
    const Case cases[] = {
        {"{'descr': '>f4', 'fortran_order': False, 'shape': (2, 3), }", six, "descr"},
        {"{'descr': '|O', 'fortran_order': False, 'shape': (2, 3), }", six, "descr"},
        {"{'descr': '<c8', 'fortran_order': False, 'shape': (3,), }", six, "descr"},
        {"{'descr': '<f4', 'fortran_order': False, 'shape': (2, 4), }", six, "data"},
        {"{'descr': '<f4', 'fortran_order': False, 'shape': (99999999999999, 99999999999), }", six, "shape"},
        {"{'descr': '<f4', 'fortran_order': False, 'shape': (0, 386666666626666444, 25), }", {}, "shape"},  // fuzzer
        {"{'descr': '<f4', 'shape': (2, 3), }", six, "npy header"},
        {"{'descr': '<f4' 'fortran_order': False}", six, "npy header"},
        {"{'descr': '<u1', 'fortran_order': False, 'shape': (2,), }", {1, 2}, "descr"},  // NumPy writes |u1
        {"{'descr': '<i2', 'fortran_order': False, 'shape': (2,), }", {1, 2, 3, 4}, "descr"},
        {"{'descr': [('x', '<f4')], 'fortran_order': False, 'shape': (1,), }", {1, 2, 3, 4}, "descr"},
        {"{'descr': '<f4', 'fortran_order': False, 'shape': (6), }", six, "npy header"},  // an int, not a tuple
        {"{'descr': '<f4', 'fortran_order': False, 'shape': (-6,), }", six, "npy header"},
        {"{'descr': '<f4', 'fortran_order': 0, 'shape': (6,), }", six, "npy header"},
        {"{'descr': '<f4', 'descr': '<f8', 'fortran_order': False, 'shape': (6,), }", six, "npy header"},
        {"{'descr': '<f4', 'fortran_order': False, 'shape': (6,), 'extra': 1}", six, "npy header"},
        {"{'descr': '<f4', 'fortran_order': False, 'shape': (6,), } x", six, "npy header"},
        {"{'descr': '<f4, 'fortran_order': False, 'shape': (6,), }", six, "descr"},  // the quote closes late
        {"", six, "npy header"},
    };
    for (const Case& c : cases) {
        const auto bytes = npy_bytes(c.dict, c.data);
        try {
            parse_npy(bytes.data(), bytes.size(), "bad.npy");
            ADD_FAILURE() << "accepted " << c.dict;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("bad.npy: ") + c.field), std::string::npos) << e.what();
        }
    }
    const auto good = npy_bytes("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }", six);
    for (size_t cut : {size_t(0), size_t(5), size_t(9), size_t(60), good.size() - 1})
        EXPECT_THROW(parse_npy(good.data(), cut, "cut.npy"), Error) << cut;
    EXPECT_THROW(read_npy("/nonexistent/x.npy"), Error);
    std::vector<uint8_t> v41 = good;
    v41[6] = 4;
    EXPECT_THROW(parse_npy(v41.data(), v41.size(), "v4.npy"), Error);
    std::vector<uint8_t> v11 = good;
    v11[7] = 1;
    EXPECT_THROW(parse_npy(v11.data(), v11.size(), "v1.1.npy"), Error);
    // Bytes after the array: a file that long was not written whole (NumPy's loader would ignore them).
    std::vector<uint8_t> trailing = good;
    trailing.insert(trailing.end(), {0, 0, 0, 0});
    try {
        parse_npy(trailing.data(), trailing.size(), "long.npy");
        ADD_FAILURE() << "trailing bytes accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "long.npy: data: expected 24 bytes of data for shape (2, 3) (got 28 bytes (4 trailing))"),
                  std::string::npos)
            << e.what();
    }
    // A negative dimension: the message quotes the header from the offending character.
    const auto negative = npy_bytes("{'descr': '<f4', 'fortran_order': False, 'shape': (-1, 3), }", six);
    try {
        parse_npy(negative.data(), negative.size(), "neg.npy");
        ADD_FAILURE() << "a negative dimension accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("expected a non-negative integer (got '-1, 3), }"), std::string::npos)
            << e.what();
    }
    // A dimension past 64 bits is quoted from its first digit (it once showed only the digits after the overflow).
    const auto huge = npy_bytes("{'descr': '<f4', 'fortran_order': False, 'shape': (98765432109876543210, 3), }", six);
    const std::string m = test::error_message([&] { parse_npy(huge.data(), huge.size(), "huge.npy"); });
    EXPECT_TRUE(test::contains(
        m, "expected a dimension that fits in 64 bits (got '98765432109876543210, 3), }' at header offset 51)"))
        << m;
    std::vector<uint8_t> long_header = good;
    long_header[9] = 0x7f;  // header length 32 KB in a 152-byte file
    EXPECT_THROW(parse_npy(long_header.data(), long_header.size(), "long.npy"), Error);
}

TEST(Npy, ReadsEveryListedDescr) {
    struct Case {
        const char* descr;
        DType dtype;
        std::vector<uint8_t> data;
        double first;
    };
    const Case cases[] = {
        {"<f2", DType::f16, {0x00, 0xbc}, -1.0},
        {"<f4", DType::f32, {0x00, 0x00, 0x20, 0x40}, 2.5},
        {"<f8", DType::f64, {0, 0, 0, 0, 0, 0, 0xf0, 0xbf}, -1.0},
        {"<i4", DType::i32, {0xfe, 0xff, 0xff, 0xff}, -2.0},
        {"<i8", DType::i64, {0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00}, 4294967296.0},
        {"|u1", DType::u8, {200}, 200.0},
        {"|b1", DType::boolean, {1}, 1.0},
    };
    for (const Case& c : cases) {
        const auto bytes =
            npy_bytes(std::string("{'descr': '") + c.descr + "', 'fortran_order': False, 'shape': (1,), }", c.data);
        const NdArray a = parse_npy(bytes.data(), bytes.size(), "d.npy");
        EXPECT_EQ(a.dtype, c.dtype) << c.descr;
        EXPECT_EQ(a.to<double>(), std::vector<double>{c.first}) << c.descr;
        EXPECT_EQ(serialize_npy(a), bytes) << c.descr;  // the writer reproduces NumPy's layout byte for byte
    }
}

TEST(Npy, Version3HeaderIsUtf8AndDoubleQuotesAreAccepted) {
    // Version 3.0 exists for UTF-8 headers; the dict is otherwise the same Python literal.
    const auto bytes =
        npy_bytes("{\"descr\": \"<f4\", \"fortran_order\": False, \"shape\": (1,)}  \u00e9", floats({7}), 3);
    EXPECT_THROW(parse_npy(bytes.data(), bytes.size(), "junk3.npy"), Error);  // text after the dict
    const auto ok = npy_bytes("{\"descr\": \"<f4\", \"fortran_order\": False, \"shape\": (1,)}", floats({7}), 3);
    EXPECT_EQ(parse_npy(ok.data(), ok.size(), "v3.npy").to<float>(), std::vector<float>{7});
}

TEST(Npy, WriterSwitchesToVersion2ForLongHeaders) {
    // 30000 dimensions of 1 make a ~90 KB shape tuple: too long for version 1.0's 2-byte header length.
    const NdArray a = NdArray::from(std::vector<float>{3.5f}, std::vector<int64_t>(30000, 1));
    const std::vector<uint8_t> b = serialize_npy(a);
    EXPECT_EQ(b[6], 2);
    const size_t header_len = b[8] | (b[9] << 8) | (b[10] << 16) | (size_t(b[11]) << 24);
    EXPECT_EQ((12 + header_len) % 64, 0u);
    EXPECT_EQ(b[12 + header_len - 1], '\n');
    const NdArray back = parse_npy(b.data(), b.size(), "v2.npy");
    EXPECT_EQ(back.shape.size(), 30000u);
    EXPECT_EQ(back.to<float>(), std::vector<float>{3.5f});
}

TEST(Npy, WriterRefusesBytesThatDoNotMatchTheShape) {
    NdArray a = NdArray::from(std::vector<float>{1, 2}, {2});
    a.bytes.pop_back();
    EXPECT_THROW(serialize_npy(a), Error);
    NdArray bf = NdArray::from(std::vector<float>{1}, {1});
    bf.dtype = DType::bf16;
    bf.bytes.resize(2);
    EXPECT_THROW(serialize_npy(bf), Error);  // NumPy has no bfloat16
}

TEST(Npy, ReadsEverySharedReferenceFile) {
    std::string root;
    SHARED_OR_SKIP(root, "reference");
    size_t files = 0, fortran = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
        if (e.path().extension() != ".npy") continue;
        const std::vector<uint8_t> raw = read_file_bytes(e.path().string());
        const NdArray a = parse_npy(raw.data(), raw.size(), e.path().string());
        EXPECT_EQ(a.bytes.size(), static_cast<size_t>(a.size()) * dtype_size(a.dtype)) << e.path();
        const std::string head(raw.begin(), raw.begin() + std::min<size_t>(raw.size(), 128));
        fortran += head.find("'fortran_order': True") != std::string::npos;
        // A C-ordered NumPy file re-serialises to the same bytes: same header, same padding, same data.
        if (head.find("'fortran_order': False") != std::string::npos) {
            EXPECT_EQ(serialize_npy(a), raw) << e.path();
        }
        ++files;
    }
    EXPECT_GE(files, 100u);
    EXPECT_GE(fortran, 1u);
}

TEST(Npy, FortranOrderThreeDimensions) {
    // Shape (2, 2, 2) with element (i, j, k) = 100i + 10j + k, stored with i fastest, then j, then k.
    std::vector<float> f;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) f.push_back(static_cast<float>(100 * i + 10 * j + k));
    std::vector<uint8_t> data(f.size() * 4);
    std::memcpy(data.data(), f.data(), data.size());
    const auto bytes = npy_bytes("{'descr': '<f4', 'fortran_order': True, 'shape': (2, 2, 2), }", data);
    EXPECT_EQ(parse_npy(bytes.data(), bytes.size(), "f3.npy").to<float>(),
              (std::vector<float>{0, 1, 10, 11, 100, 101, 110, 111}));
}
