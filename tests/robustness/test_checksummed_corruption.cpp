// Damage behind valid checksums: each case changes a section's payload and
// rewrites its length and CRC-32, as a buggy or hostile writer would, so the
// decoder's own checks are what stand between the bytes and a crash.
//
// Where the format leaves room for a different but valid mesh (a changed
// coordinate, a lever switched), decode may return one; it must still
// terminate and return a well-formed mesh. Where the format rules the value
// out (a face count that does not match, a component count that does not,
// a quantization of 22 bits), decode must throw drm::Error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "drm_sections.h"
#include "header_fields.h"
#include "samples.h"
#include "verdicts.h"

namespace {

using drm_test::Bytes;
using drm_test::HeaderFields;
using drm_test::Verdicts;

constexpr size_t kHeader = 0, kConnectivity = 1, kGeometry = 2, kVertexOrder = 3;
const char* const kSectionNames[] = {"header", "connectivity", "geometry", "vertex order"};

std::vector<Bytes> payloadsOf(const drm_test::Sample& s) {
    std::vector<drm_test::SectionSpan> sections;
    EXPECT_TRUE(drm_test::parseSections(s.bytes, &sections)) << s.name;
    return drm_test::payloadsOf(s.bytes, sections);
}

std::string where(const drm_test::Sample& s, size_t section) {
    return s.name + " " + (section < 4 ? kSectionNames[section] : "extra") + " section";
}

HeaderFields headerOf(const drm_test::Sample& s) {
    HeaderFields h;
    EXPECT_TRUE(drm_test::readHeader(payloadsOf(s)[kHeader], &h)) << s.name << ": header not as docs/format.md says";
    return h;
}

Bytes withHeader(const drm_test::Sample& s, const HeaderFields& h) {
    return drm_test::withPayload(s.bytes, kHeader, drm_test::writeHeader(h));
}

Bytes randomBytes(std::mt19937& rng, size_t size) {
    Bytes b(size);
    for (uint8_t& x : b) x = uint8_t(rng());
    return b;
}

// Applies change to a copy of each sample's header and hands the result to check.
void forEachHeader(const std::function<void(const drm_test::Sample&, HeaderFields&)>& change,
                   const std::function<void(const Bytes&, const std::string&)>& check, const std::string& what) {
    for (const drm_test::Sample& s : drm_test::samples()) {
        HeaderFields h = headerOf(s);
        change(s, h);
        check(withHeader(s, h), s.name + ": " + what);
    }
}

TEST(ChecksummedCorruption, EveryPayloadBitFlipIsRefusedOrSound) {
    Verdicts v("payload bit flips behind fresh checksums");
    // samples() starts with coreSamples(), which get every bit flipped.
    for (size_t n = 0; n < drm_test::samples().size(); ++n) {
        const drm_test::Sample& s = drm_test::samples()[n];
        const bool core = n < drm_test::coreSamples().size();
        const std::vector<Bytes> payloads = payloadsOf(s);
        for (size_t section = 0; section < payloads.size(); ++section)
            for (size_t i = 0; i < payloads[section].size(); ++i)
                for (int bit = 0; bit < 8; ++bit) {
                    if (!core && bit != int(i % 8)) continue;  // every bit of the core samples only
                    Bytes p = payloads[section];
                    p[i] ^= uint8_t(1u << bit);
                    v.refusedOrSound(drm_test::withPayload(s.bytes, section, p),
                                     where(s, section) + ": bit " + std::to_string(bit) + " of byte " +
                                         std::to_string(i) + " flipped");
                }
    }
}

TEST(ChecksummedCorruption, ShortenedPayloadsAreRefusedOrSound) {
    Verdicts v("shortened payloads behind fresh checksums");
    for (const drm_test::Sample& s : drm_test::samples()) {
        const std::vector<Bytes> payloads = payloadsOf(s);
        for (size_t section = 0; section < payloads.size(); ++section)
            for (size_t size = 0; size < payloads[section].size(); ++size) {
                const Bytes p(payloads[section].begin(), payloads[section].begin() + std::ptrdiff_t(size));
                const Bytes b = drm_test::withPayload(s.bytes, section, p);
                const std::string label = where(s, section) + " cut to " + std::to_string(size) + " bytes";
                // The header has no slack, and an empty rank or geometry
                // stream cannot hold a mesh with faces.
                if (section == kHeader || size == 0) v.refused(b, label);
                else v.refusedOrSound(b, label);
            }
    }
}

TEST(ChecksummedCorruption, LengthenedPayloadsAreRefusedOrSound) {
    std::mt19937 rng(5);
    Verdicts v("lengthened payloads behind fresh checksums");
    for (const drm_test::Sample& s : drm_test::samples()) {
        const std::vector<Bytes> payloads = payloadsOf(s);
        for (size_t section = 0; section < payloads.size(); ++section)
            for (size_t extra : {1, 2, 3, 4, 17, 300}) {
                for (bool random : {false, true}) {
                    Bytes p = payloads[section];
                    const Bytes tail = random ? randomBytes(rng, extra) : Bytes(extra, 0);
                    p.insert(p.end(), tail.begin(), tail.end());
                    const std::string label =
                        where(s, section) + " + " + std::to_string(extra) + (random ? " random" : " zero") + " bytes";
                    const Bytes b = drm_test::withPayload(s.bytes, section, p);
                    if (section == kHeader) v.refused(b, label, drm::ErrorKind::Corrupt);
                    else v.refusedOrSound(b, label);
                }
            }
    }
}

TEST(ChecksummedCorruption, RandomPayloadsAreRefusedOrSound) {
    std::mt19937 rng(6);
    Verdicts v("random payloads behind fresh checksums");
    for (const drm_test::Sample& s : drm_test::samples()) {
        const std::vector<Bytes> payloads = payloadsOf(s);
        for (size_t section = 0; section < payloads.size(); ++section)
            for (int i = 0; i < 40; ++i) {
                // Half keep the size (the raw geometry coder checks it), half do not.
                const size_t size = i % 2 ? payloads[section].size() : rng() % (2 * payloads[section].size() + 8);
                v.refusedOrSound(drm_test::withPayload(s.bytes, section, randomBytes(rng, size)),
                                 where(s, section) + " replaced by random bytes #" + std::to_string(i));
            }
    }
}

TEST(ChecksummedCorruption, SectionsSwappedBetweenFilesAreRefusedOrSound) {
    // The header of one mesh over the ranks or vertices of another.
    Verdicts v("sections from another file");
    for (const drm_test::Sample& a : drm_test::samples())
        for (const drm_test::Sample& b : drm_test::samples()) {
            if (&a == &b) continue;
            const std::vector<Bytes> from = payloadsOf(b);
            const size_t sections = payloadsOf(a).size();
            for (size_t section = 0; section < sections && section < from.size(); ++section)
                v.refusedOrSound(drm_test::withPayload(a.bytes, section, from[section]),
                                 where(a, section) + " taken from " + b.name);
        }
}

TEST(ChecksummedCorruption, MissingOrExtraVertexOrderSectionIsRefused) {
    Verdicts v("vertex order section present without its flag, or absent with it");
    for (const drm_test::Sample& s : drm_test::samples()) {
        std::vector<Bytes> payloads = payloadsOf(s);
        if (payloads.size() > kVertexOrder) payloads.resize(kVertexOrder);
        else payloads.push_back(Bytes(payloads[kGeometry].size() / 2 + 1, 0x55));
        v.refused(drm_test::assemble(s.bytes.data(), payloads),
                  s.name + (payloads.size() > kVertexOrder ? " with" : " without") + " a vertex order section");
    }
}

TEST(ChecksummedCorruption, UnknownHeaderFlagsAreRefused) {
    // Bits 0-6 and 8-10 may be set on their own (docs/format.md, "Header
    // payload"); bit 7, attributes, needs the sections it announces, bit 11
    // a connectivity section in two parts (no sample has one), and bits 12
    // to 15 must be 0. A new flag must come with a reader that knows it, so
    // readers without it refuse it.
    Verdicts v("unknown header flags");
    for (int bit = 7; bit < 16; ++bit) {
        if (bit == 8 || bit == 9 || bit == 10) continue;
        forEachHeader([&](const drm_test::Sample&, HeaderFields& h) { h.flags |= uint16_t(1u << bit); },
                      [&](const Bytes& b, const std::string& label) { v.refused(b, label, drm::ErrorKind::Corrupt); },
                      "flag bit " + std::to_string(bit) + " set");
    }
}

TEST(ChecksummedCorruption, ToggledKnownFlagsAreRefusedOrSound) {
    Verdicts v("known header flags toggled");
    for (int bit : {0, 1, 2, 3, 4, 5, 6, 8, 9, 10})
        forEachHeader([&](const drm_test::Sample&, HeaderFields& h) { h.flags ^= uint16_t(1u << bit); },
                      [&](const Bytes& b, const std::string& label) { v.refusedOrSound(b, label); },
                      "flag bit " + std::to_string(bit) + " toggled");
}

TEST(ChecksummedCorruption, ImpossibleVertexCountsAreRefused) {
    Verdicts v("impossible vertex counts");
    const uint64_t counts[] = {0, 0xFFFFFFFEull, 0xFFFFFFFFull, uint64_t(1) << 40, UINT64_MAX};
    for (uint64_t count : counts)
        forEachHeader([&](const drm_test::Sample&, HeaderFields& h) { h.vertexCount = count; },
                      [&](const Bytes& b, const std::string& label) { v.refused(b, label); },
                      "vertex count " + std::to_string(count));
}

TEST(ChecksummedCorruption, VertexCountsOffByOneAreRefusedOrSound) {
    // One more vertex can hide in the padding of a raw geometry section at
    // 1 or 2 bits; it is then an extra isolated vertex, a valid mesh.
    Verdicts v("vertex counts off by one");
    for (int delta : {-1, 1})
        forEachHeader([&](const drm_test::Sample&, HeaderFields& h) { h.vertexCount += uint64_t(int64_t(delta)); },
                      [&](const Bytes& b, const std::string& label) { v.refusedOrSound(b, label); },
                      "vertex count " + std::string(delta > 0 ? "+1" : "-1"));
}

TEST(ChecksummedCorruption, FaceCountsThatDoNotMatchAreRefused) {
    Verdicts v("face counts that do not match the ranks");
    const std::pair<const char*, std::function<uint64_t(uint64_t)>> changes[] = {
        {"+1", [](uint64_t f) { return f + 1; }},
        {"-1", [](uint64_t f) { return f - 1; }},
        {"0", [](uint64_t) { return uint64_t(0); }},
        {"doubled", [](uint64_t f) { return 2 * f; }},
        {"the largest allowed", [](uint64_t) { return uint64_t(0x55555554); }},
        {"past the limit", [](uint64_t) { return uint64_t(0x55555555); }},
        {"2^64 - 1", [](uint64_t) { return UINT64_MAX; }},
    };
    for (const auto& change : changes)
        forEachHeader([&](const drm_test::Sample&, HeaderFields& h) { h.faceCount = change.second(h.faceCount); },
                      [&](const Bytes& b, const std::string& label) { v.refused(b, label, drm::ErrorKind::Corrupt); },
                      std::string("face count ") + change.first);
}

TEST(ChecksummedCorruption, ComponentCountsThatDoNotMatchAreRefused) {
    // One component more reads a start triangle past the end of the
    // connectivity section, one fewer leaves faces undecoded. (The start
    // triangles themselves are in the connectivity section:
    // tests/unit/connectivity/test_start_triangle.cpp damages them.)
    Verdicts v("component counts that do not match the connectivity section");
    for (int64_t delta : {-1, 1, 2, 1000000})
        forEachHeader(
            [&](const drm_test::Sample&, HeaderFields& h) { h.componentCount += uint64_t(delta); },
            [&](const Bytes& b, const std::string& label) { v.refused(b, label, drm::ErrorKind::Corrupt); },
            "component count " + std::to_string(delta));
}

TEST(ChecksummedCorruption, OutOfRangeHeaderFieldsAreRefused) {
    Verdicts v("header fields out of range");
    struct Change {
        const char* what;
        drm::ErrorKind kind;
        std::function<void(HeaderFields&)> apply;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const Change changes[] = {
        {"0 quantization bits", drm::ErrorKind::Corrupt, [](HeaderFields& h) { h.bits = 0; }},
        {"22 quantization bits", drm::ErrorKind::Corrupt, [](HeaderFields& h) { h.bits = 22; }},
        {"255 quantization bits", drm::ErrorKind::Corrupt, [](HeaderFields& h) { h.bits = 255; }},
        {"predictor 0 (auto is never stored)", drm::ErrorKind::Corrupt, [](HeaderFields& h) { h.predictor = 0; }},
        {"predictor 3", drm::ErrorKind::Corrupt, [](HeaderFields& h) { h.predictor = 3; }},
        {"predictor 255", drm::ErrorKind::Corrupt, [](HeaderFields& h) { h.predictor = 255; }},
        {"connectivity coder 0", drm::ErrorKind::Unsupported, [](HeaderFields& h) { h.connectivityCoder = 0; }},
        {"connectivity coder 3", drm::ErrorKind::Unsupported, [](HeaderFields& h) { h.connectivityCoder = 3; }},
        {"geometry coder 0", drm::ErrorKind::Unsupported, [](HeaderFields& h) { h.geometryCoder = 0; }},
        {"geometry coder 5", drm::ErrorKind::Unsupported, [](HeaderFields& h) { h.geometryCoder = 5; }},
        {"geometry coder 255", drm::ErrorKind::Unsupported, [](HeaderFields& h) { h.geometryCoder = 255; }},
        {"origin x NaN", drm::ErrorKind::Corrupt, [=](HeaderFields& h) { h.origin[0] = nan; }},
        {"origin y +inf", drm::ErrorKind::Corrupt, [=](HeaderFields& h) { h.origin[1] = inf; }},
        {"origin z -inf", drm::ErrorKind::Corrupt, [=](HeaderFields& h) { h.origin[2] = -inf; }},
        {"step 0", drm::ErrorKind::Corrupt, [](HeaderFields& h) { h.step = 0; }},
        {"step -0", drm::ErrorKind::Corrupt, [](HeaderFields& h) { h.step = -0.0; }},
        {"step -1", drm::ErrorKind::Corrupt, [](HeaderFields& h) { h.step = -1; }},
        {"step NaN", drm::ErrorKind::Corrupt, [=](HeaderFields& h) { h.step = nan; }},
        {"step +inf", drm::ErrorKind::Corrupt, [=](HeaderFields& h) { h.step = inf; }},
    };
    for (const Change& c : changes)
        forEachHeader([&](const drm_test::Sample&, HeaderFields& h) { c.apply(h); },
                      [&](const Bytes& b, const std::string& label) { v.refused(b, label, c.kind); }, c.what);
}

TEST(ChecksummedCorruption, OtherValidHeaderValuesAreRefusedOrSound) {
    // Values the header allows but the rest of the file was not coded for:
    // another grid, predictor or geometry coder. Positions may overflow to
    // infinity in float (a huge step); the indices must still be sound.
    Verdicts v("other valid header values");
    struct Change {
        std::string what;
        std::function<void(HeaderFields&)> apply;
    };
    std::vector<Change> changes = {
        {"predictors swapped", [](HeaderFields& h) { h.predictor = uint8_t(3 - h.predictor); }},
        {"geometry coders swapped", [](HeaderFields& h) { h.geometryCoder = uint8_t(3 - h.geometryCoder); }},
        {"geometry coder 3 (refine) over another payload", [](HeaderFields& h) { h.geometryCoder = 3; }},
        {"geometry coder 4 (sorted) over another payload", [](HeaderFields& h) { h.geometryCoder = 4; }},
        {"geometry coder 2 over a refine payload", [](HeaderFields& h) { if (h.geometryCoder == 3) h.geometryCoder = 2; }},
        // The topological coder over the ranks' sections, and
        // the ranks over the topological coder's.
        {"connectivity coders swapped", [](HeaderFields& h) { h.connectivityCoder = uint8_t(3 - h.connectivityCoder); }},
        {"smallest step", [](HeaderFields& h) { h.step = std::numeric_limits<double>::denorm_min(); }},
        {"step 1e300", [](HeaderFields& h) { h.step = 1e300; }},
        {"origin 1e308", [](HeaderFields& h) { h.origin[0] = 1e308; }},
    };
    for (int bits = 1; bits <= 21; ++bits)
        changes.push_back({std::to_string(bits) + " quantization bits", [=](HeaderFields& h) { h.bits = uint8_t(bits); }});
    for (const Change& c : changes)
        forEachHeader([&](const drm_test::Sample&, HeaderFields& h) { c.apply(h); },
                      [&](const Bytes& b, const std::string& label) { v.refusedOrSound(b, label); }, c.what);
}

// A normal section whose bit width lies outside kMinNormalBits ..
// kMaxNormalBits (behind a fresh checksum) is refused as corrupt: the
// octahedral decoder is defined for those widths only.
TEST(ChecksummedCorruption, NormalBitWidthsOutOfRangeAreRefused) {
    // A bumpy 12 x 12 grid with its own normals.
    drm::Mesh mesh;
    const int side = 12;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const float z = 0.1f * float((x * 7 + y * 3) % 5);
            mesh.positions.insert(mesh.positions.end(), {float(x), float(y), z});
            const float n[3] = {0.1f * float(x % 3), 0.1f * float(y % 4), 1.0f};
            const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (float c : n) mesh.normals.push_back(c / length);
        }
    for (int y = 0; y + 1 < side; ++y)
        for (int x = 0; x + 1 < side; ++x) {
            const uint32_t v = uint32_t(y * side + x);
            mesh.triangles.insert(mesh.triangles.end(), {v, v + 1, v + side, v + 1, v + side + 1, v + side});
        }
    const Bytes file = drm::encode(mesh).bytes;
    std::vector<drm_test::SectionSpan> sections;
    ASSERT_TRUE(drm_test::parseSections(file, &sections));
    const std::vector<Bytes> payloads = drm_test::payloadsOf(file, sections);
    size_t normals = payloads.size();
    for (size_t s = kGeometry + 1; s < payloads.size(); ++s)
        if (payloads[s].size() > 4 && payloads[s][0] == 2) normals = s;  // semantic 2: normals
    ASSERT_LT(normals, payloads.size()) << "no normal section";
    ASSERT_EQ(int(payloads[normals][4]), drm::kDefaultNormalBits);  // the section's bit width
    EXPECT_NO_THROW(drm::decode(file));
    Verdicts v("normal bit widths out of range");
    for (int bits : {0, 1, drm::kMinNormalBits - 1, drm::kMaxNormalBits + 1, 24, 31, 32}) {
        Bytes payload = payloads[normals];
        payload[4] = uint8_t(bits);
        v.refused(drm_test::withPayload(file, normals, payload), "normal bits " + std::to_string(bits),
                  drm::ErrorKind::Corrupt);
    }
}

TEST(ChecksummedCorruption, RawGeometryOfTheWrongSizeIsRefused) {
    Verdicts v("raw geometry sections of the wrong size");
    std::mt19937 rng(7);
    for (const drm_test::Sample& s : drm_test::samples()) {
        if (headerOf(s).geometryCoder != 1) continue;
        const Bytes geometry = payloadsOf(s)[kGeometry];
        for (long delta : {-long(geometry.size()), -2L, -1L, 1L, 2L, long(geometry.size())}) {
            Bytes p = geometry;
            p.resize(size_t(long(p.size()) + delta), uint8_t(rng()));
            v.refused(drm_test::withPayload(s.bytes, kGeometry, p),
                      s.name + " raw geometry " + (delta > 0 ? "+" : "") + std::to_string(delta) + " bytes",
                      drm::ErrorKind::Corrupt);
        }
    }
}

}  // namespace
