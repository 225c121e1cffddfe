// The repairs section (mesh/repair_section.h): every list comes back from
// the section exactly, read in the decoder's two steps; a clean section
// costs little; counts the section cannot hold and indices out of range are
// refused before anything is allocated, naming what is wrong; and undoCut
// turns traversal faces back into the input's: copies to their originals,
// turned faces back over, repeated faces and faces repeating a vertex
// appended.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "mesh/repair_section.h"

namespace drm {
namespace {

template <class F>
std::string corruptionOf(F f) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Corrupt) << e.what();
        return e.what();
    }
    return "";
}

Repairs someRepairs(uint32_t vertexCount, size_t traversalFaces) {
    Repairs r;
    r.copyOf = {0, 0, 3, 17, 17, vertexCount - 1};
    r.looseTriangles = {1, 1, 2, 5, 6, 5};
    r.flipped.assign(traversalFaces, 0);
    for (size_t f = 0; f < traversalFaces; f += 7) r.flipped[f] = 1;
    r.duplicateOf = {0, uint32_t(traversalFaces - 1), 4};
    r.duplicateReversed = {1, 0, 1};
    return r;
}

TEST(RepairSection, EveryListComesBackInTwoSteps) {
    for (uint32_t vertexCount : {20u, 1000u, 70000u}) {
        const size_t traversalFaces = 2 * vertexCount;
        const Repairs r = someRepairs(vertexCount, traversalFaces);
        const std::vector<uint8_t> bytes = encodeRepairs(r, vertexCount);
        const uint64_t faceCount = traversalFaces + r.looseCount() + r.duplicateOf.size();
        RepairReader reader(bytes.data(), bytes.size(), vertexCount, r.copyOf.size(), faceCount);
        EXPECT_EQ(reader.repairs().copyOf, r.copyOf);
        EXPECT_EQ(reader.repairs().looseTriangles, r.looseTriangles);
        EXPECT_EQ(reader.duplicateCount(), r.duplicateOf.size());
        reader.readAfterTraversal(traversalFaces);
        EXPECT_EQ(reader.repairs().flipped, r.flipped);
        EXPECT_EQ(reader.repairs().duplicateOf, r.duplicateOf);
        EXPECT_EQ(reader.repairs().duplicateReversed, r.duplicateReversed);
    }
}

TEST(RepairSection, NoFlipsCostOneBit) {
    // Copies only: the flip bits are a single "none".
    Repairs r;
    r.copyOf = {2, 2, 9};
    r.flipped.assign(100000, 0);
    const std::vector<uint8_t> bytes = encodeRepairs(r, 50);
    EXPECT_LT(bytes.size(), 16u);
    RepairReader reader(bytes.data(), bytes.size(), 50, 3, 100000);
    reader.readAfterTraversal(100000);
    EXPECT_EQ(reader.repairs().flipped, r.flipped);
    EXPECT_TRUE(reader.repairs().duplicateOf.empty());
}

TEST(RepairSection, CountsAndIndicesOutOfRangeAreRefused) {
    const uint32_t vertexCount = 20;
    const Repairs r = someRepairs(vertexCount, 40);
    const std::vector<uint8_t> bytes = encodeRepairs(r, vertexCount);
    const uint64_t faceCount = 40 + r.looseCount() + r.duplicateOf.size();
    // More copies than the section's bits could name.
    EXPECT_EQ(corruptionOf([&] { RepairReader(bytes.data(), bytes.size(), vertexCount, 1u << 30, faceCount); }),
              "corrupt file: the repairs section claims 1073741824 vertex copies, more than its " +
                  std::to_string(bytes.size()) + " bytes can hold");
    // A copy of a vertex past the count the reader is given.
    EXPECT_EQ(corruptionOf([&] { RepairReader(bytes.data(), bytes.size(), 10, r.copyOf.size(), faceCount); }),
              "corrupt file: the repairs section copies vertex 17 of 10");
    // More faces repeating a vertex than the header's faces.
    EXPECT_EQ(corruptionOf([&] { RepairReader(bytes.data(), bytes.size(), vertexCount, r.copyOf.size(), 1); }),
              "corrupt file: the repairs section claims 2 faces repeating a vertex, more than the header's 1 faces");
    // Repeated faces past what the header's faces leave room for.
    EXPECT_EQ(corruptionOf([&] { RepairReader(bytes.data(), bytes.size(), vertexCount, r.copyOf.size(), 4); }),
              "corrupt file: the repairs section claims 3 repeated faces, more than the header's faces leave room for");
    // A repeated face past the traversal's faces: face 39 of 40 read as
    // one of 35 (positions of both take 6 bits; no flips before them).
    Repairs one;
    one.flipped.assign(40, 0);
    one.duplicateOf = {39};
    one.duplicateReversed = {0};
    const std::vector<uint8_t> oneBytes = encodeRepairs(one, vertexCount);
    RepairReader reader(oneBytes.data(), oneBytes.size(), vertexCount, 0, 41);
    EXPECT_EQ(corruptionOf([&] { reader.readAfterTraversal(35); }),
              "corrupt file: a repeated face in the repairs section repeats face 39 of 35");
}

TEST(RepairSection, TruncatedAndGarbageSectionsAreRefusedOrInRange) {
    const uint32_t vertexCount = 300;
    const Repairs r = someRepairs(vertexCount, 600);
    const std::vector<uint8_t> bytes = encodeRepairs(r, vertexCount);
    const uint64_t faceCount = 600 + r.looseCount() + r.duplicateOf.size();
    for (size_t cut = 0; cut + 1 < bytes.size(); ++cut)
        EXPECT_NE(corruptionOf([&] {
                      RepairReader reader(bytes.data(), cut, vertexCount, r.copyOf.size(), faceCount);
                      reader.readAfterTraversal(600);
                  }),
                  "")
            << "cut at " << cut;
    std::mt19937 rng(14);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<uint8_t> garbage(1 + rng() % 40);
        for (uint8_t& b : garbage) b = uint8_t(rng());
        try {
            RepairReader reader(garbage.data(), garbage.size(), 50, rng() % 8, 100);
            reader.readAfterTraversal(60);
            for (uint32_t v : reader.repairs().copyOf) ASSERT_LT(v, 50u);
            for (uint32_t v : reader.repairs().looseTriangles) ASSERT_LT(v, 50u);
            for (uint32_t f : reader.repairs().duplicateOf) ASSERT_LT(f, 60u);
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Corrupt) << e.what();
        }
    }
}

TEST(RepairSection, UndoCutGivesBackTheInputsFaces) {
    // Four vertices; vertex 4 is a copy of 0, vertex 5 of 2.
    std::vector<uint32_t> t = {4, 1, 2, 0, 2, 3, 1, 3, 5};
    Repairs r;
    r.copyOf = {0, 2};
    r.flipped = {0, 1, 0};
    r.duplicateOf = {2, 0};
    r.duplicateReversed = {1, 0};
    r.looseTriangles = {3, 3, 1};
    undoCut(t, r, 4);
    const std::vector<uint32_t> expected = {0, 1, 2,  // copy 4 back to 0
                                            0, 3, 2,  // turned back over
                                            1, 3, 2,  // copy 5 back to 2
                                            1, 2, 3,  // face 2 repeated the other way round
                                            0, 1, 2,  // face 0 repeated
                                            3, 3, 1};
    EXPECT_EQ(t, expected);
    EXPECT_EQ(r.looseCount(), 1u);
}

}  // namespace
}  // namespace drm
