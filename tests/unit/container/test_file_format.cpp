// The .drm container (container/file_format.h): writeFile and readFile are
// each other's inverse for every header field and optional section; the
// bytes follow the layout of docs/format.md (signature, version, then each
// section as its length, its CRC-32 over the version and the payload, and
// the payload); and readFile refuses, with a message naming what is wrong,
// a missing signature, any version but the current one, a section failing its
// checksum, a header field out of range and bytes past the last section.
// headerProblem is the one test both sides make.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "container/byte_io.h"
#include "container/crc32.h"
#include "container/file_format.h"
#include "drmcodec/drmcodec.h"

namespace drm {
namespace {

// The message of the Error f throws (of the given kind), or "".
template <class F>
std::string errorOf(F f, ErrorKind kind = ErrorKind::Corrupt) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), kind) << e.what();
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

FileHeader someHeader() {
    FileHeader h;
    h.vertexCount = 500;
    h.faceCount = 996;
    h.grid.bits = 14;
    h.grid.origin[0] = -1.5;
    h.grid.origin[1] = 2.25;
    h.grid.origin[2] = 1e-3;
    h.grid.step = 0.001953125;
    h.predictor = Predictor::Parallelogram;
    h.curvature = true;
    h.levers = Levers::none();
    h.levers.angleOrder = true;
    h.levers.boundaryFlag = true;
    h.componentCount = 2;
    return h;
}

const std::vector<uint8_t> kConnectivity = {1, 2, 3, 4, 5};
const std::vector<uint8_t> kGeometry = {9, 8, 7};

// One section as docs/format.md defines it: varint length, CRC-32 of the
// format version's two bytes followed by the payload, the payload. (With
// coverVersion false, a checksum of the payload alone.)
void appendSection(std::vector<uint8_t>& file, const std::vector<uint8_t>& payload, bool coverVersion = true) {
    ByteWriter w;
    w.varint(payload.size());
    const uint8_t stored[2] = {uint8_t(kFormatVersion & 0xFF), uint8_t(kFormatVersion >> 8)};
    w.u32(coverVersion ? crc32(payload.data(), payload.size(), crc32(stored, 2)) : crc32(payload.data(), payload.size()));
    w.bytes(payload);
    file.insert(file.end(), w.buffer().begin(), w.buffer().end());
}

// A file whose header section holds `header` verbatim, with valid framing.
std::vector<uint8_t> fileWithHeaderPayload(const std::vector<uint8_t>& header, bool coverVersion = true) {
    std::vector<uint8_t> file(kSignature, kSignature + sizeof kSignature);
    file.push_back(uint8_t(kFormatVersion & 0xFF));
    file.push_back(uint8_t(kFormatVersion >> 8));
    appendSection(file, header, coverVersion);
    appendSection(file, kConnectivity, coverVersion);
    appendSection(file, kGeometry, coverVersion);
    return file;
}

// A header payload in the current syntax, field by field.
struct RawHeader {
    uint16_t flags = 0;
    uint8_t bits = 12, predictor = uint8_t(Predictor::Midpoint), connectivity = uint8_t(ConnectivityCoder::Ranks),
            geometry = uint8_t(GeometryCoder::SpanningTree);
    double origin[3] = {0, 0, 0}, step = 0.5;
    uint64_t vertices = 10, faces = 12, components = 1;
    std::vector<uint8_t> bytes() const {
        ByteWriter w;
        w.u16(flags);
        w.u8(bits);
        w.u8(predictor);
        w.u8(connectivity);
        w.u8(geometry);
        for (double o : origin) w.f64(o);
        w.f64(step);
        w.varint(vertices);
        w.varint(faces);
        w.varint(components);
        return w.buffer();
    }
};

TEST(FileFormat, EveryHeaderFieldAndSectionReadsBack) {
    FileHeader h = someHeader();
    h.keepsVertexOrder = true;
    h.hasRepairs = true;
    h.copyCount = 4;
    h.mortonNumbering = false;
    h.twoParts = true;
    h.geometryCoder = GeometryCoder::Refine;
    const std::vector<uint8_t> order = {42}, repairs = {6, 6}, empty;
    const std::vector<std::vector<uint8_t>> attributes = {{1}, empty, {2, 3}};
    FileParts written;
    const std::vector<uint8_t> file = writeFile(h, kConnectivity, kGeometry, order, repairs, attributes, &written);
    const FileParts parts = readFile(file.data(), file.size());
    const FileHeader& r = parts.header;
    EXPECT_EQ(parts.formatVersion, kFormatVersion);
    EXPECT_EQ(r.vertexCount, h.vertexCount);
    EXPECT_EQ(r.faceCount, h.faceCount);
    EXPECT_EQ(r.grid.bits, h.grid.bits);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(r.grid.origin[k], h.grid.origin[k]);
    EXPECT_EQ(r.grid.step, h.grid.step);
    EXPECT_EQ(r.predictor, h.predictor);
    EXPECT_EQ(r.curvature, h.curvature);
    EXPECT_EQ(leversName(r.levers), leversName(h.levers));
    EXPECT_EQ(r.keepsVertexOrder, true);
    EXPECT_EQ(r.hasRepairs, true);
    EXPECT_EQ(r.copyCount, 4u);
    EXPECT_EQ(r.mortonNumbering, false);
    EXPECT_EQ(r.twoParts, true);
    EXPECT_EQ(r.geometryCoder, GeometryCoder::Refine);
    EXPECT_EQ(r.connectivityCoder, ConnectivityCoder::Ranks);
    EXPECT_EQ(r.componentCount, h.componentCount);
    EXPECT_EQ(r.attributeSections, attributes.size());  // set from the list
    auto bytesOf = [](const uint8_t* p, size_t n) { return std::vector<uint8_t>(p, p + n); };
    EXPECT_EQ(bytesOf(parts.connectivity, parts.connectivitySize), kConnectivity);
    EXPECT_EQ(bytesOf(parts.geometry, parts.geometrySize), kGeometry);
    EXPECT_EQ(bytesOf(parts.vertexOrder, parts.vertexOrderSize), order);
    EXPECT_EQ(bytesOf(parts.repairs, parts.repairsSize), repairs);
    ASSERT_EQ(parts.attributes.size(), attributes.size());
    for (size_t a = 0; a < attributes.size(); ++a)
        EXPECT_EQ(bytesOf(parts.attributes[a].data, parts.attributes[a].size), attributes[a]);
    // What writeFile reports is what readFile finds.
    EXPECT_EQ(written.headerBytes, parts.headerBytes);
    EXPECT_EQ(written.attributeBytes, parts.attributeBytes);
    EXPECT_EQ(written.connectivitySize, parts.connectivitySize);
    EXPECT_EQ(written.vertexOrderSize, parts.vertexOrderSize);
    EXPECT_EQ(written.repairsSize, parts.repairsSize);
    EXPECT_EQ(written.header.attributeSections, 3u);
    EXPECT_EQ(parts.headerBytes + parts.connectivitySize + parts.geometrySize + parts.vertexOrderSize +
                  parts.repairsSize + parts.attributeBytes,
              file.size());
}

TEST(FileFormat, OptionalSectionsAreWrittenOnlyWhenTheHeaderSaysSo) {
    const FileHeader h = someHeader();
    const std::vector<uint8_t> plain = writeFile(h, kConnectivity, kGeometry, {}, {}, {}, nullptr);
    // Lists passed without their flags are not written.
    const std::vector<uint8_t> ignored = writeFile(h, kConnectivity, kGeometry, {1, 2, 3}, {4, 5}, {}, nullptr);
    EXPECT_EQ(ignored, plain);
    const FileParts parts = readFile(plain.data(), plain.size());
    EXPECT_EQ(parts.vertexOrder, nullptr);
    EXPECT_EQ(parts.repairs, nullptr);
    EXPECT_TRUE(parts.attributes.empty());
    EXPECT_EQ(parts.attributeBytes, 0u);
}

TEST(FileFormat, LayoutIsSignatureVersionAndChecksummedSections) {
    const std::vector<uint8_t> file = writeFile(someHeader(), kConnectivity, kGeometry, {}, {}, {}, nullptr);
    ASSERT_GT(file.size(), 10u);
    const uint8_t signature[8] = {0x89, 'D', 'R', 'M', '\r', '\n', 0x1A, '\n'};
    EXPECT_EQ(std::memcmp(file.data(), signature, 8), 0);
    EXPECT_EQ(file[8] | (file[9] << 8), kFileFormatVersion);
    // Rebuilt from the header payload readFile finds, with this test's own
    // framing, the file is the same bytes.
    const FileParts parts = readFile(file.data(), file.size());
    ByteReader r(file.data() + 10, file.size() - 10, "test");
    const size_t headerSize = size_t(r.varint("length"));
    r.u32("checksum");
    const uint8_t* header = r.bytes(headerSize, "header");
    EXPECT_EQ(fileWithHeaderPayload(std::vector<uint8_t>(header, header + headerSize)), file);
    EXPECT_EQ(parts.headerBytes, file.size() - kConnectivity.size() - kGeometry.size());
}

TEST(FileFormat, AHandWrittenHeaderReadsAsWritten) {
    RawHeader raw;
    raw.flags = kFlagCurvature | kFlagGapClosing | kFlagSectionNumbering;
    raw.origin[1] = -7;
    const std::vector<uint8_t> file = fileWithHeaderPayload(raw.bytes());
    const FileParts parts = readFile(file.data(), file.size());
    EXPECT_TRUE(parts.header.curvature);
    EXPECT_TRUE(parts.header.levers.gapClosing);
    EXPECT_FALSE(parts.header.levers.topologicalFilter);
    EXPECT_FALSE(parts.header.mortonNumbering);
    EXPECT_EQ(parts.header.grid.origin[1], -7);
    EXPECT_EQ(parts.header.grid.step, 0.5);
    EXPECT_EQ(parts.header.vertexCount, 10u);
    EXPECT_EQ(parts.header.faceCount, 12u);
}

TEST(FileFormat, NotADrmFile) {
    EXPECT_EQ(errorOf([] { readFile(nullptr, 0); }), "empty file: not a .drm file");
    const uint8_t text[] = "ply\nformat ascii 1.0\n";
    EXPECT_EQ(errorOf([&] { readFile(text, sizeof text); }), "not a .drm file: the signature is missing");
    EXPECT_EQ(errorOf([&] { readFile(kSignature, 5); }), "not a .drm file: the signature is missing");
}

TEST(FileFormat, EveryOtherVersionIsUnsupported) {
    for (uint16_t version : {uint16_t(0), uint16_t(1), uint16_t(kFileFormatVersion - 1), uint16_t(kFileFormatVersion + 1),
                             uint16_t(0xFFFF)}) {
        std::vector<uint8_t> file = writeFile(someHeader(), kConnectivity, kGeometry, {}, {}, {}, nullptr);
        file[8] = uint8_t(version & 0xFF);
        file[9] = uint8_t(version >> 8);
        const std::string message = errorOf([&] { readFile(file.data(), file.size()); }, ErrorKind::Unsupported);
        EXPECT_TRUE(contains(message, "unsupported .drm format version " + std::to_string(version))) << message;
        // Earlier versions are pre-release formats: the message says what to do.
        if (version > 0 && version < kFormatVersion)
            EXPECT_TRUE(contains(message, "a pre-release format this reader does not read (it reads version " +
                                              std::to_string(kFormatVersion) + "); encode the mesh again"))
                << message;
        else
            EXPECT_TRUE(contains(message, ": this reader knows version " + std::to_string(kFormatVersion))) << message;
    }
}

TEST(FileFormat, EveryChecksumCoversItsSectionAndTheVersion) {
    const std::vector<uint8_t> file = writeFile(someHeader(), kConnectivity, kGeometry, {}, {}, {}, nullptr);
    // A flipped payload byte fails its own section's checksum, named.
    for (const char* section : {"geometry", "connectivity"}) {
        std::vector<uint8_t> bad = file;
        const size_t at = std::string(section) == "geometry" ? bad.size() - 1 : bad.size() - kGeometry.size() - 5 - 1;
        bad[at] ^= 0x40;
        const std::string message = errorOf([&] { readFile(bad.data(), bad.size()); });
        EXPECT_TRUE(contains(message, std::string("the ") + section + " section")) << message;
        EXPECT_TRUE(contains(message, "fails its checksum")) << message;
    }
    // A checksum of the payload alone, without the version before it,
    // does not pass.
    const std::vector<uint8_t> uncovered = fileWithHeaderPayload(RawHeader().bytes(), false);
    EXPECT_EQ(errorOf([&] { readFile(uncovered.data(), uncovered.size()); }),
              "corrupt file: the header section (offset 15) fails its checksum");
    const std::vector<uint8_t> covered = fileWithHeaderPayload(RawHeader().bytes());
    EXPECT_NO_THROW(readFile(covered.data(), covered.size()));
}

TEST(FileFormat, TruncationAndTrailingBytesAreCorrupt) {
    const std::vector<uint8_t> file = writeFile(someHeader(), kConnectivity, kGeometry, {}, {}, {}, nullptr);
    for (size_t cut = sizeof kSignature + 2; cut < file.size(); ++cut)
        EXPECT_NE(errorOf([&] { readFile(file.data(), cut); }), "") << cut;
    std::vector<uint8_t> longer = file;
    longer.insert(longer.end(), {0, 0});
    EXPECT_EQ(errorOf([&] { readFile(longer.data(), longer.size()); }),
              "corrupt file: 2 unexpected bytes after the last section");
}

TEST(FileFormat, HeaderFieldsOutOfRangeAreNamed) {
    struct Case {
        RawHeader raw;
        std::string expected;
        ErrorKind kind;
    };
    std::vector<Case> cases;
    auto add = [&](const char* expected, ErrorKind kind, auto change) {
        RawHeader raw;
        change(raw);
        cases.push_back({raw, expected, kind});
    };
    add("unknown header flags 4096", ErrorKind::Corrupt, [](RawHeader& r) { r.flags = 4096; });
    add("quantization bits 22 out of range 1..21", ErrorKind::Corrupt, [](RawHeader& r) { r.bits = 22; });
    add("quantization bits 0 out of range", ErrorKind::Corrupt, [](RawHeader& r) { r.bits = 0; });
    add("unknown predictor 0", ErrorKind::Corrupt, [](RawHeader& r) { r.predictor = 0; });
    add("unknown connectivity coder 3", ErrorKind::Unsupported, [](RawHeader& r) { r.connectivity = 3; });
    add("unknown geometry coder 0", ErrorKind::Unsupported, [](RawHeader& r) { r.geometry = 0; });
    add("unknown geometry coder 200", ErrorKind::Unsupported, [](RawHeader& r) { r.geometry = 200; });
    add("the grid step is not a positive number", ErrorKind::Corrupt, [](RawHeader& r) { r.step = 0; });
    add("the grid step is not a positive number", ErrorKind::Corrupt,
        [](RawHeader& r) { r.step = std::numeric_limits<double>::quiet_NaN(); });
    add("the bounding box origin is not a finite float", ErrorKind::Corrupt, [](RawHeader& r) { r.origin[2] = 1e300; });
    add("the vertex count is zero", ErrorKind::Corrupt, [](RawHeader& r) { r.vertices = 0; });
    add("field \"vertex count\"", ErrorKind::Corrupt, [](RawHeader& r) { r.vertices = kMaxVertexCount + 1; });
    add("field \"face count\"", ErrorKind::Corrupt, [](RawHeader& r) { r.faces = kMaxFaceCount + 1; });
    add("field \"component count\"", ErrorKind::Corrupt, [](RawHeader& r) { r.components = 13; });
    add("a topological connectivity section in two parts", ErrorKind::Corrupt, [](RawHeader& r) {
        r.connectivity = uint8_t(ConnectivityCoder::Topological);
        r.flags = kFlagTwoParts;
    });
    for (const Case& c : cases) {
        const std::vector<uint8_t> file = fileWithHeaderPayload(c.raw.bytes());
        const std::string message = errorOf([&] { readFile(file.data(), file.size()); }, c.kind);
        EXPECT_TRUE(contains(message, c.expected)) << "expected \"" << c.expected << "\" in: " << message;
    }
    // Bytes left over in the header section.
    std::vector<uint8_t> longer = RawHeader().bytes();
    longer.push_back(0);
    const std::vector<uint8_t> file = fileWithHeaderPayload(longer);
    EXPECT_EQ(errorOf([&] { readFile(file.data(), file.size()); }),
              "corrupt file: 1 unexpected bytes at the end of the header");
}

TEST(FileFormat, SectionNumberingIsAFlagMortonOrderTheDefault) {
    RawHeader raw;
    const std::vector<uint8_t> morton = fileWithHeaderPayload(raw.bytes());
    EXPECT_TRUE(readFile(morton.data(), morton.size()).header.mortonNumbering);
    raw.flags = kFlagSectionNumbering;
    const std::vector<uint8_t> section = fileWithHeaderPayload(raw.bytes());
    EXPECT_FALSE(readFile(section.data(), section.size()).header.mortonNumbering);
    // Every flag the format knows reads back (those announcing sections
    // or fields left out).
    raw.flags = kKnownFlags & ~(kFlagAttributes | kFlagRepairs | kFlagVertexOrder);
    const std::vector<uint8_t> all = fileWithHeaderPayload(raw.bytes());
    const FileHeader h = readFile(all.data(), all.size()).header;
    EXPECT_EQ(leversName(h.levers), "all");
    EXPECT_TRUE(h.curvature);
    EXPECT_TRUE(h.twoParts);
    EXPECT_FALSE(h.mortonNumbering);
}

TEST(FileFormat, HeaderProblemIsTheTestWriteFileMakes) {
    EXPECT_EQ(headerProblem(someHeader()), "");
    struct Case {
        void (*change)(FileHeader&);
        const char* expected;
    };
    const Case cases[] = {
        {[](FileHeader& h) { h.grid.bits = 0; }, "quantization bits 0 out of range 1..21"},
        {[](FileHeader& h) { h.grid.step = -1; }, "the grid step is not a positive number"},
        {[](FileHeader& h) { h.vertexCount = 0; }, "0 vertices (a file holds 1 to 4294967294)"},
        {[](FileHeader& h) { h.faceCount = kMaxFaceCount + 1; }, "1431655765 faces (a file holds at most 1431655764)"},
        {[](FileHeader& h) { h.copyCount = 1; }, "1 vertex copies for 500 vertices and 996 faces"},
        {[](FileHeader& h) { h.componentCount = h.faceCount + 1; }, "more components than faces"},
        {[](FileHeader& h) { h.predictor = Predictor::Auto; }, "unknown predictor 0"},
        {[](FileHeader& h) { h.geometryCoder = GeometryCoder::Auto; }, "unknown geometry coder 0"},
        {[](FileHeader& h) {
             h.connectivityCoder = ConnectivityCoder::Topological;
             h.twoParts = true;
         },
         "a topological connectivity in two parts"},
    };
    for (const Case& c : cases) {
        FileHeader h = someHeader();
        c.change(h);
        EXPECT_EQ(headerProblem(h), c.expected);
        // writeFile refuses the same header before writing anything.
        const std::string message =
            errorOf([&] { writeFile(h, kConnectivity, kGeometry, {}, {}, {}, nullptr); }, ErrorKind::InvalidInput);
        EXPECT_EQ(message, std::string("cannot encode this mesh: the file would hold ") + c.expected);
    }
    // More attribute sections than a file may hold.
    FileHeader h = someHeader();
    const std::vector<std::vector<uint8_t>> tooMany(kMaxAttributeSections + 1, std::vector<uint8_t>{1});
    EXPECT_NE(errorOf([&] { writeFile(h, kConnectivity, kGeometry, {}, {}, tooMany, nullptr); }, ErrorKind::InvalidInput),
              "");
}

}  // namespace
}  // namespace drm
