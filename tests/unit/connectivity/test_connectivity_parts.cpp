// The connectivity in two parts that decode side by side
// (connectivity_parts.h). Checked here: that every test mesh, split, comes
// back exactly (the encoder's own check decodes and compares); that one
// thread and two decode the same mesh; that large meshes are split by
// default and small ones not; and that the parts' payload refuses each
// field out of range.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ranks_only.h"
#include "connectivity/connectivity_parts.h"
#include "drmcodec/drmcodec.h"
#include "drm_sections.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

std::vector<drm_test::NamedMesh> meshesToSplit() {
    std::vector<drm_test::NamedMesh> meshes;
    for (const char* name : {"blobby-3cc.ply", "bunny-lres.ply", "elephant-with-holes.ply", "fandisk.ply", "genus3.ply",
                             "mech-holes-shark.ply", "nefertiti.ply", "soup.ply", "torus.ply", "tray-bottom.ply"})
        meshes.push_back({name, drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/" + name)});
    meshes.push_back({"mixed", drm_test::mixedMesh()});
    meshes.push_back({"needing repairs", drm_test::meshNeedingRepairs()});
    for (drm_test::NamedMesh& m : drm_test::smallMeshes()) meshes.push_back(std::move(m));
    return meshes;
}

TEST(ConnectivityParts, EveryMeshSplitComesBackExactly) {
    for (const drm_test::NamedMesh& m : meshesToSplit()) {
        SCOPED_TRACE(m.name);
        EncodeOptions options = drm_test::ranksOnly();
        options.connectivityParts = 2;
        options.verify = true;  // decodes the file and compares faces and grid points; throws on a mismatch
        Encoded split;
        ASSERT_NO_THROW(split = encode(m.mesh, options));
        if (m.mesh.vertexCount() >= 2 && m.mesh.faceCount() > 0) EXPECT_EQ(split.stats.connectivityParts, 2);
        options.connectivityParts = 1;
        const Encoded whole = encode(m.mesh, options);
        EXPECT_EQ(whole.stats.connectivityParts, 1);
        EXPECT_EQ(decode(split.bytes).mesh.faceCount(), decode(whole.bytes).mesh.faceCount());
    }
}

TEST(ConnectivityParts, OneThreadAndTwoDecodeTheSameMesh) {
    for (const drm_test::NamedMesh& m : meshesToSplit()) {
        SCOPED_TRACE(m.name);
        EncodeOptions options = drm_test::ranksOnly();
        options.connectivityParts = 2;
        const Encoded encoded = encode(m.mesh, options);
        DecodeOptions one, two;
        one.threads = 1;
        two.threads = 2;
        const Decoded a = decode(encoded.bytes.data(), encoded.bytes.size(), one);
        const Decoded b = decode(encoded.bytes.data(), encoded.bytes.size(), two);
        EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
        EXPECT_EQ(a.quantized, b.quantized);
        EXPECT_EQ(a.faceRank, b.faceRank);
        EXPECT_EQ(a.stats.rankHistogram, b.stats.rankHistogram);
    }
}

TEST(ConnectivityParts, LargeMeshesAreSplitByDefault) {
    const Mesh large = drm_test::gridPatch(128, false, 0.2, 7);  // 32,768 faces
    ASSERT_EQ(large.faceCount(), kTwoPartsFromFaces);
    EncodeOptions options = drm_test::ranksOnly();
    options.verify = true;
    const Encoded split = encode(large, options);
    EXPECT_EQ(split.stats.connectivityParts, 2);
    options.connectivityParts = 1;
    EXPECT_EQ(encode(large, options).stats.connectivityParts, 1);
    const Mesh smaller = drm_test::gridPatch(126, false, 0.2, 7);
    ASSERT_LT(smaller.faceCount(), kTwoPartsFromFaces);
    EXPECT_EQ(encode(smaller, drm_test::ranksOnly()).stats.connectivityParts, 1);
    EXPECT_EQ(inspect(split.bytes).stats.connectivityParts, 2);
}

// A cancel while part 1 decodes ends the decoding with a Cancelled error,
// on one thread or two (the thread of part 2 is waited for, and told to
// stop, before the error leaves decode()).
TEST(ConnectivityParts, CancelStopsBothParts) {
    const Encoded split = encode(drm_test::gridPatch(128, false, 0.2, 7), drm_test::ranksOnly());
    ASSERT_EQ(split.stats.connectivityParts, 2);
    for (int threads : {1, 2}) {
        SCOPED_TRACE(threads);
        DecodeOptions options;
        options.threads = threads;
        options.progress = [](double fraction, const char*) { return fraction < 0.3; };  // part 1 a third done
        try {
            decode(split.bytes.data(), split.bytes.size(), options);
            ADD_FAILURE() << "not cancelled";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Cancelled) << e.what();
        }
    }
}

TEST(ConnectivityParts, OptionsOutOfRangeAreRefused) {
    const Mesh mesh = drm_test::icosphere(2);
    for (int parts : {-1, 3}) {
        EncodeOptions options = drm_test::ranksOnly();
        options.connectivityParts = parts;
        try {
            encode(mesh, options);
            ADD_FAILURE() << parts << " parts accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
            EXPECT_NE(std::string(e.what()).find("connectivity parts"), std::string::npos) << e.what();
        }
    }
    const Encoded encoded = encode(mesh, drm_test::ranksOnly());
    DecodeOptions negative;
    negative.threads = -1;
    EXPECT_THROW(decode(encoded.bytes.data(), encoded.bytes.size(), negative), Error);
}

// A file whose first part would start a component on vertices that are all
// the second part's (its split moved to 1, under a fresh checksum) is
// refused as corrupt, naming the start triangle: the two parts could
// otherwise hold the same faces.
TEST(ConnectivityParts, FirstPartStartingPastItsVerticesIsCorrupt) {
    Mesh mesh = drm_test::icosphere(2);
    drm_test::addVertex(mesh, -10, -10, -10);  // grid point (0, 0, 0): vertex 0, in no face
    EncodeOptions options = drm_test::ranksOnly();
    options.connectivityParts = 2;
    const Encoded encoded = encode(mesh, options);
    ASSERT_EQ(encoded.stats.connectivityParts, 2);
    std::vector<drm_test::SectionSpan> sections;
    ASSERT_TRUE(drm_test::parseSections(encoded.bytes, &sections));
    const std::vector<uint8_t> payload = drm_test::payloadsOf(encoded.bytes, sections)[1];
    const uint64_t vertices = mesh.vertexCount();
    ConnectivityParts parts = readConnectivityParts(payload.data(), payload.size(), vertices, encoded.stats.components,
                                                    mesh.faceCount());
    ASSERT_GT(parts.split, 1u);
    const std::vector<uint8_t> first(parts.first, parts.first + parts.firstSize),
        second(parts.second, parts.second + parts.secondSize);
    parts.split = 1;
    parts.keptInSecond.clear();
    const std::vector<uint8_t> moved = drm_test::withPayload(encoded.bytes, 1, writeConnectivityParts(parts, first, second));
    try {
        decode(moved);
        ADD_FAILURE() << "decoded";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Corrupt) << e.what();
        EXPECT_NE(std::string(e.what()).find("past the first part's vertices"), std::string::npos) << e.what();
    }
}

// The payload alone: what is written reads back, and each field out of
// range is refused by name.
TEST(ConnectivityParts, PayloadReadsBackAndRefusesFieldsOutOfRange) {
    ConnectivityParts layout;
    layout.split = 5;
    layout.firstComponents = 2;
    layout.firstFaces = 7;
    layout.keptInSecond = {0, 3, 4};
    const std::vector<uint8_t> first = {1, 2, 3}, second = {9, 8};
    const std::vector<uint8_t> bytes = writeConnectivityParts(layout, first, second);
    const ConnectivityParts read = readConnectivityParts(bytes.data(), bytes.size(), 10, 3, 12);
    EXPECT_EQ(read.split, 5u);
    EXPECT_EQ(read.firstComponents, 2u);
    EXPECT_EQ(read.firstFaces, 7u);
    EXPECT_EQ(read.keptInSecond, layout.keptInSecond);
    EXPECT_EQ(std::vector<uint8_t>(read.first, read.first + read.firstSize), first);
    EXPECT_EQ(std::vector<uint8_t>(read.second, read.second + read.secondSize), second);

    auto refusal = [](const std::vector<uint8_t>& b, uint64_t vertices, uint64_t components, uint64_t faces) {
        try {
            readConnectivityParts(b.data(), b.size(), vertices, components, faces);
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Corrupt);
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(refusal(bytes, 5, 3, 12).find("connectivity split"), std::string::npos);  // m must be below 5
    EXPECT_NE(refusal(bytes, 10, 1, 12).find("components"), std::string::npos);
    EXPECT_NE(refusal(bytes, 10, 3, 6).find("faces"), std::string::npos);
    EXPECT_NE(refusal(bytes, 9, 3, 12).find("kept vert"), std::string::npos);  // vertex 4 of part 2's 4
    EXPECT_NE(refusal(bytes, 1, 3, 12).find("fewer than two vertices"), std::string::npos);
    for (size_t cut = 0; cut + second.size() < bytes.size(); ++cut)  // truncated before part 1's bytes end
        EXPECT_FALSE(refusal(std::vector<uint8_t>(bytes.begin(), bytes.begin() + cut), 10, 3, 12).empty()) << cut;
    ConnectivityParts atZero = layout;
    atZero.split = 0;
    const std::vector<uint8_t> zero = writeConnectivityParts(atZero, first, second);
    EXPECT_NE(refusal(zero, 10, 3, 12).find("vertex 0"), std::string::npos);
}

}  // namespace
}  // namespace drm
