// Damaged and foreign files as they arrive in practice: cut short, bits
// flipped in transit, text-mode line-end conversion, garbage, bytes
// appended, another version. The checksums and the container checks must
// catch every one of these: drm::decode has to throw drm::Error, with a
// message that says which kind of failure it is, and never crash, hang or
// return. (test_checksummed_corruption.cpp damages payloads behind valid
// checksums, to reach the checks past the container.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "drm_sections.h"
#include "option_sets.h"
#include "samples.h"
#include "test_meshes.h"
#include "verdicts.h"

namespace {

using drm_test::Bytes;
using drm_test::Verdicts;

const uint8_t kSignature[8] = {0x89, 'D', 'R', 'M', '\r', '\n', 0x1A, '\n'};

Bytes randomBytes(std::mt19937& rng, size_t size) {
    Bytes b(size);
    for (uint8_t& x : b) x = uint8_t(rng());
    return b;
}

Bytes prefix(const Bytes& b, size_t size) { return Bytes(b.begin(), b.begin() + std::ptrdiff_t(size)); }

std::vector<drm_test::SectionSpan> sectionsOf(const drm_test::Sample& s) {
    std::vector<drm_test::SectionSpan> sections;
    EXPECT_TRUE(drm_test::parseSections(s.bytes, &sections)) << s.name << " is not laid out as docs/format.md says";
    return sections;
}

TEST(CorruptFiles, EmptyInputIsRefused) {
    Verdicts v("empty input");
    v.refused(Bytes(), "an empty vector", drm::ErrorKind::Corrupt);
    try {
        drm::decode(nullptr, 0);
        ADD_FAILURE() << "decode(nullptr, 0) returned";
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::Corrupt) << e.what();
    }
}

TEST(CorruptFiles, ZerosAreNotADrmFile) {
    Verdicts v("zeros");
    for (size_t size : {1, 2, 7, 8, 9, 10, 11, 16, 64, 1000, 65536})
        v.refused(Bytes(size, 0), std::to_string(size) + " zero bytes", drm::ErrorKind::Corrupt);
}

TEST(CorruptFiles, RandomGarbageIsRefused) {
    std::mt19937 rng(1);
    Verdicts v("random garbage");
    for (int i = 0; i < 300; ++i) {
        const size_t size = 1 + rng() % (i < 200 ? 64 : 4000);
        v.refused(randomBytes(rng, size), "garbage #" + std::to_string(i), drm::ErrorKind::Corrupt);
    }
}

TEST(CorruptFiles, GarbageAfterTheSignatureIsRefused) {
    std::mt19937 rng(2);
    Verdicts v("garbage after signature and version");
    for (int i = 0; i < 300; ++i) {
        Bytes b(kSignature, kSignature + 8);
        b.push_back(uint8_t(drm::kFileFormatVersion));  // the version read, little-endian
        b.push_back(uint8_t(drm::kFileFormatVersion >> 8));
        const Bytes tail = randomBytes(rng, rng() % (i < 200 ? 40 : 3000));
        b.insert(b.end(), tail.begin(), tail.end());
        v.refused(b, "garbage #" + std::to_string(i));
    }
}

TEST(CorruptFiles, WrongVersionIsUnsupported) {
    Verdicts v("wrong version");
    for (const drm_test::Sample& s : drm_test::samples())
        for (unsigned version : {0u, unsigned(drm::kFileFormatVersion) + 1, 256u, 257u, 0xFFFFu}) {
            Bytes b = s.bytes;
            b[8] = uint8_t(version);
            b[9] = uint8_t(version >> 8);
            v.refused(b, s.name + " as version " + std::to_string(version), drm::ErrorKind::Unsupported);
        }
}

// A file relabelled with an earlier, pre-release version is refused as
// unsupported (the reader reads one version), before any section is read.
TEST(CorruptFiles, EarlierVersionsAreUnsupported) {
    Verdicts v("relabelled version");
    for (const drm_test::Sample& s : drm_test::samples())
        for (int version = 1; version < drm::kFileFormatVersion; ++version) {
            Bytes b = s.bytes;
            b[8] = uint8_t(version);
            b[9] = uint8_t(version >> 8);
            v.refused(b, s.name + " as version " + std::to_string(version), drm::ErrorKind::Unsupported);
        }
}

TEST(CorruptFiles, DamagedSignatureIsNotADrmFile) {
    Verdicts v("damaged signature");
    for (const drm_test::Sample& s : drm_test::samples()) {
        for (size_t i = 0; i < 8; ++i) {
            Bytes b = s.bytes;
            b[i] ^= 0x20;
            v.refused(b, s.name + " with signature byte " + std::to_string(i) + " changed", drm::ErrorKind::Corrupt);
        }
        // What a text-mode transfer does: CR LF -> LF everywhere, or LF -> CR LF.
        Bytes lfOnly, crlf;
        for (size_t i = 0; i < s.bytes.size(); ++i) {
            if (!(s.bytes[i] == '\r' && i + 1 < s.bytes.size() && s.bytes[i + 1] == '\n')) lfOnly.push_back(s.bytes[i]);
            if (s.bytes[i] == '\n') crlf.push_back('\r');
            crlf.push_back(s.bytes[i]);
        }
        v.refused(lfOnly, s.name + " with CR LF turned into LF", drm::ErrorKind::Corrupt);
        v.refused(crlf, s.name + " with LF turned into CR LF", drm::ErrorKind::Corrupt);
    }
}

TEST(CorruptFiles, TruncationAtEverySectionBoundaryIsRefused) {
    Verdicts v("truncated at section boundaries");
    for (const drm_test::Sample& s : drm_test::samples()) {
        std::set<size_t> cuts = {0, 1, 7, 8, 9, 10};
        for (const drm_test::SectionSpan& section : sectionsOf(s))
            for (size_t cut : {section.start, section.start + 1, section.checksumAt, section.checksumAt + 2,
                               section.payloadAt, section.payloadAt + 1, section.payloadAt + section.payloadSize / 2,
                               section.end() - 1, section.end()})
                cuts.insert(cut);
        for (size_t cut : cuts)
            if (cut < s.bytes.size()) v.refused(prefix(s.bytes, cut), s.name + " cut to " + std::to_string(cut) + " bytes");
    }
}

TEST(CorruptFiles, TruncationAtRandomOffsetsIsRefused) {
    std::mt19937 rng(3);
    Verdicts v("truncated at random offsets");
    for (const drm_test::Sample& s : drm_test::samples())
        for (int i = 0; i < 200; ++i) {
            const size_t cut = rng() % s.bytes.size();
            v.refused(prefix(s.bytes, cut), s.name + " cut to " + std::to_string(cut) + " bytes");
        }
}

TEST(CorruptFiles, EverySingleBitFlipIsRefused) {
    // CRC-32 catches every single-bit error in a payload; flips in the
    // preamble, the lengths and the checksums themselves must be caught by
    // the container checks.
    Verdicts v("single bit flips");
    for (const drm_test::Sample& s : drm_test::samples()) {
        const bool everyBit = s.bytes.size() <= 4096;
        for (size_t i = 0; i < s.bytes.size(); ++i)
            for (int bit = 0; bit < 8; ++bit) {
                if (!everyBit && bit != int(i % 8)) continue;
                Bytes b = s.bytes;
                b[i] ^= uint8_t(1u << bit);
                v.refused(b, s.name + " with bit " + std::to_string(bit) + " of byte " + std::to_string(i) + " flipped");
            }
    }
}

TEST(CorruptFiles, EveryByteReplacementIsRefused) {
    Verdicts v("byte replacements");
    for (const drm_test::Sample& s : drm_test::samples())
        for (size_t i = 0; i < s.bytes.size(); ++i)
            for (uint8_t value : {uint8_t(~s.bytes[i]), uint8_t(0), uint8_t(0xFF), uint8_t(s.bytes[i] + 1)}) {
                if (value == s.bytes[i]) continue;
                Bytes b = s.bytes;
                b[i] = value;
                v.refused(b, s.name + " with byte " + std::to_string(i) + " set to " + std::to_string(value));
            }
}

TEST(CorruptFiles, TrailingBytesAreRefused) {
    std::mt19937 rng(4);
    Verdicts v("trailing bytes");
    for (const drm_test::Sample& s : drm_test::samples()) {
        for (size_t extra : {1, 2, 3, 4, 5, 16, 1000}) {
            Bytes zeros = s.bytes, noise = s.bytes;
            zeros.resize(zeros.size() + extra, 0);
            const Bytes tail = randomBytes(rng, extra);
            noise.insert(noise.end(), tail.begin(), tail.end());
            v.refused(zeros, s.name + " + " + std::to_string(extra) + " zero bytes", drm::ErrorKind::Corrupt);
            v.refused(noise, s.name + " + " + std::to_string(extra) + " random bytes", drm::ErrorKind::Corrupt);
        }
        // A whole well-formed section more than the header announces.
        for (const Bytes& payload : {Bytes(), Bytes{0}, randomBytes(rng, 40)}) {
            Bytes b = s.bytes;
            drm_test::appendSection(b, payload);
            v.refused(b, s.name + " + a section of " + std::to_string(payload.size()) + " bytes", drm::ErrorKind::Corrupt);
        }
        // The file twice over.
        Bytes twice = s.bytes;
        twice.insert(twice.end(), s.bytes.begin(), s.bytes.end());
        v.refused(twice, s.name + " twice", drm::ErrorKind::Corrupt);
    }
}

TEST(CorruptFiles, CancellationIsReported) {
    for (const drm_test::Sample& s : drm_test::samples()) {
        try {
            drm::decode(s.bytes, [](double, const char*) { return false; });
            ADD_FAILURE() << s.name << ": a decode cancelled from the start returned";
        } catch (const drm::Error& e) {
            EXPECT_EQ(e.kind(), drm::ErrorKind::Cancelled) << s.name << ": " << e.what();
        }
    }
}

TEST(CorruptFiles, UndamagedFilesDecode) {
    // The premise of every test here: the undamaged files are accepted. The
    // samples, and every small test mesh with every option set (the
    // fuzzer's seeds), quantizations of 1 and 2 bits included, where many
    // vertices share a grid point.
    for (const drm_test::Sample& s : drm_test::samples()) {
        const drm_test::Outcome o = drm_test::decodeGuarded(s.bytes, s.name);
        EXPECT_FALSE(o.threw) << s.name << ": " << o.message;
        EXPECT_EQ(o.meshProblem, "") << s.name;
    }
    for (const drm_test::NamedMesh& m : drm_test::smallMeshes())
        for (const drm_test::NamedOptions& options : drm_test::optionSets()) {
            const std::string name = m.name + "/" + options.name;
            const drm_test::Outcome o = drm_test::decodeGuarded(drm::encode(m.mesh, options.options).bytes, name);
            EXPECT_FALSE(o.threw) << name << ": the encoder wrote a file its decoder refuses: " << o.message;
            EXPECT_EQ(o.meshProblem, "") << name;
        }
}

TEST(CorruptFiles, FuzzerSeedsAndRegressionsAreRefusedOrSound) {
    // Files the fuzzer found interesting (and any reproducers saved after a
    // fix) are re-checked here on every build, sanitizers or not. The seeds
    // may predate a format change, so they need not decode.
    Verdicts v("fuzzer seeds and regressions");
    for (const char* dir : {"../fuzz/seeds", "../fuzz/regressions"}) {
        if (!std::filesystem::is_directory(dir)) continue;
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
            if (!entry.is_regular_file()) continue;
            std::ifstream in(entry.path(), std::ios::binary);
            const Bytes b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            v.refusedOrSound(b, entry.path().string());
        }
    }
}

}  // namespace
