// Byte IO of the file format: layout, round trips, and errors that name the
// field and the file offset.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "container/byte_io.h"
#include "drmcodec/drmcodec.h"

namespace {

// The message of the drm::Error thrown by f, or "" if it throws none; every
// error a reader throws on bad bytes is of kind Corrupt. The tests below
// compare whole messages where the text is the behaviour under test: a
// ByteReader's refusals name the section, the field and the file offset.
template <class F>
std::string errorOf(F f) {
    try {
        f();
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::Corrupt) << e.what();
        return e.what();
    }
    return "";
}

uint64_t bitsOf(double d) {
    uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    return bits;
}

double doubleOf(uint64_t bits) {
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return d;
}

TEST(ByteWriter, LittleEndianLayout) {
    drm::ByteWriter w;
    w.u8(0xAB);
    w.u16(0x0201);
    w.u32(0x06050403);
    w.f64(1.0);  // 0x3FF0000000000000
    w.varint(300);
    const std::vector<uint8_t> expected = {0xAB, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0, 0, 0, 0,
                                           0,    0,    0xF0, 0x3F, 0xAC, 0x02};
    EXPECT_EQ(w.buffer(), expected);
    EXPECT_EQ(w.size(), expected.size());
}

TEST(ByteWriter, VarintLengths) {
    const std::pair<uint64_t, size_t> cases[] = {
        {0, 1}, {127, 1}, {128, 2}, {16383, 2}, {16384, 3}, {uint64_t(1) << 63, 10}, {UINT64_MAX, 10}};
    for (const auto& c : cases) {
        drm::ByteWriter w;
        w.varint(c.first);
        EXPECT_EQ(w.size(), c.second) << c.first;
    }
}

TEST(ByteReader, RoundTripsEverything) {
    std::mt19937_64 rng(21);
    std::vector<uint64_t> varints = {0, 1, 127, 128, 255, 256, UINT32_MAX, uint64_t(UINT32_MAX) + 1,
                                     (uint64_t(1) << 63) - 1, uint64_t(1) << 63, UINT64_MAX};
    for (int i = 0; i < 1000; ++i) varints.push_back(rng() >> (rng() % 64));
    const uint64_t doubleBits[] = {bitsOf(0.0), bitsOf(-0.0), bitsOf(1e-310), bitsOf(-1.5e300),
                                   bitsOf(std::numeric_limits<double>::infinity()),
                                   0x7FF8000000000001ull /* a NaN payload */, rng()};
    const std::vector<uint8_t> blob = {1, 2, 3, 0, 255};

    drm::ByteWriter w;
    w.u8(0);
    w.u8(255);
    w.u16(0);
    w.u16(65535);
    w.u32(0);
    w.u32(UINT32_MAX);
    for (uint64_t b : doubleBits) w.f64(doubleOf(b));
    for (uint64_t v : varints) w.varint(v);
    w.bytes(blob);
    w.bytes(blob.data(), 2);
    w.bytes(nullptr, 0);

    const std::vector<uint8_t>& buf = w.buffer();
    drm::ByteReader r(buf.data(), buf.size(), "test");
    EXPECT_EQ(r.u8("a"), 0);
    EXPECT_EQ(r.u8("b"), 255);
    EXPECT_EQ(r.u16("c"), 0);
    EXPECT_EQ(r.u16("d"), 65535);
    EXPECT_EQ(r.u32("e"), 0u);
    EXPECT_EQ(r.u32("f"), UINT32_MAX);
    for (uint64_t b : doubleBits) EXPECT_EQ(bitsOf(r.f64("g")), b);
    for (uint64_t v : varints) EXPECT_EQ(r.varint("h"), v);
    const uint8_t* p = r.bytes(blob.size(), "i");
    EXPECT_EQ(std::vector<uint8_t>(p, p + blob.size()), blob);
    EXPECT_EQ(r.remaining(), 2u);
    EXPECT_EQ(r.count("j", 1), 1u);
    EXPECT_EQ(r.count("k", 2), 2u);
    EXPECT_EQ(r.offset(), buf.size());
    EXPECT_EQ(r.remaining(), 0u);
    EXPECT_NE(r.bytes(0, "empty"), nullptr);
}

TEST(ByteReader, TruncationNamesFieldAndFileOffset) {
    const uint8_t data[] = {1, 2, 3};
    drm::ByteReader r(data, sizeof data, "header", 34);
    EXPECT_EQ(r.u8("magic"), 1);
    EXPECT_EQ(errorOf([&] { r.u32("face count"); }),
              "truncated file: header field \"face count\" needs 2 more bytes at offset 35");
    EXPECT_EQ(r.u16("vertex count"), 0x0302);
    EXPECT_EQ(errorOf([&] { r.u8("bits"); }),
              "truncated file: header field \"bits\" needs 1 more byte at offset 37");
    EXPECT_EQ(errorOf([&] { r.f64("origin"); }),
              "truncated file: header field \"origin\" needs 8 more bytes at offset 37");
    EXPECT_EQ(errorOf([&] { r.bytes(SIZE_MAX, "payload"); }),
              "truncated file: header field \"payload\" needs " + std::to_string(SIZE_MAX) +
                  " more bytes at offset 37");
}

TEST(ByteReader, TruncatedVarintNamesItsStart) {
    const uint8_t data[] = {0x05, 0x80, 0x80};
    drm::ByteReader r(data, sizeof data, "rank section", 100);
    EXPECT_EQ(r.varint("length"), 5u);
    EXPECT_EQ(errorOf([&] { r.varint("face count"); }),
              "truncated file: rank section field \"face count\" needs 1 more byte at offset 101");
}

TEST(ByteReader, CountAboveLimitIsCorrupt) {
    drm::ByteWriter w;
    w.u8(7);
    w.varint(99999999);
    drm::ByteReader r(w.buffer().data(), w.size(), "header", 36);
    r.u8("version");
    EXPECT_EQ(errorOf([&] { r.count("face count", 1234); }),
              "corrupt file: header field \"face count\" = 99999999 exceeds the limit 1234 at offset 37");
}

TEST(ByteReader, MalformedVarintsAreCorrupt) {
    const std::vector<std::vector<uint8_t>> bad = {
        std::vector<uint8_t>(11, 0x80),                                      // longer than 10 bytes
        {0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x02},        // bit 64
        {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x81, 0x00},  // continues past 10
        {0x80, 0x00},                                                        // overlong zero
        {0xFF, 0x80, 0x00},                                                  // overlong 127
    };
    for (const std::vector<uint8_t>& b : bad) {
        drm::ByteReader r(b.data(), b.size(), "header", 10);
        const std::string message = errorOf([&] { r.varint("size"); });  // Corrupt
        EXPECT_NE(message.find("header field \"size\" "), std::string::npos) << message;  // names the field
        EXPECT_NE(message.find(" at offset 10"), std::string::npos) << message;          // and where
    }
}

TEST(ByteReader, GarbageNeverReadsOutOfBounds) {
    // Under AddressSanitizer any read past the copy below is fatal.
    std::mt19937 rng(22);
    for (int trial = 0; trial < 2000; ++trial) {
        std::vector<uint8_t> data(rng() % 24);
        for (uint8_t& b : data) b = uint8_t(rng());
        drm::ByteReader r(data.data(), data.size(), "garbage");
        try {
            for (;;) {
                switch (rng() % 6) {
                case 0: r.u8("x"); break;
                case 1: r.u16("x"); break;
                case 2: r.u32("x"); break;
                case 3: r.f64("x"); break;
                case 4: r.count("x", rng()); break;
                default: r.bytes(rng() % 8, "x"); break;
                }
                ASSERT_LE(r.offset(), data.size());
            }
        } catch (const drm::Error& e) {
            EXPECT_EQ(e.kind(), drm::ErrorKind::Corrupt) << e.what();
            EXPECT_NE(std::string(e.what()).find("garbage field \"x\""), std::string::npos) << e.what();  // names the field
        }
    }
}

}  // namespace
