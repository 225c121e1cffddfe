// The vertex-order section (mesh/vertex_order.h): any permutation comes
// back exactly, orders that follow the surface code small (each index is
// coded as its difference from the one before), and what is not a
// permutation, or is cut short, is refused as corrupt. Through encode():
// keepVertexOrder gives back the input numbering at the cost of the
// section.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "mesh/vertex_order.h"

namespace drm {
namespace {

// The message of the Corrupt Error f throws, or "" if it throws none.
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

std::vector<uint32_t> roundTrip(const std::vector<uint32_t>& order) {
    const std::vector<uint8_t> bytes = encodeVertexOrder(order);
    return decodeVertexOrder(bytes.data(), bytes.size(), order.size());
}

TEST(VertexOrderSection, EveryPermutationRoundTrips) {
    std::mt19937 rng(5);
    for (size_t n : {size_t(1), size_t(2), size_t(3), size_t(17), size_t(1000), size_t(65537)}) {
        std::vector<uint32_t> order(n);
        std::iota(order.begin(), order.end(), 0u);
        EXPECT_EQ(roundTrip(order), order) << n;
        std::reverse(order.begin(), order.end());
        EXPECT_EQ(roundTrip(order), order) << n;
        std::shuffle(order.begin(), order.end(), rng);
        EXPECT_EQ(roundTrip(order), order) << n;
    }
    // The widest differences: the last index of a huge range, then the
    // first, then back (zigzagged, 33 bits).
    const std::vector<uint32_t> extremes = {0xFFFFFFFDu, 0, 0xFFFFFFFCu};
    const std::vector<uint8_t> bytes = encodeVertexOrder(extremes);
    // Decoding allocates one entry per vertex: check against a count that
    // makes these three valid without allocating billions.
    EXPECT_EQ(corruptionOf([&] { decodeVertexOrder(bytes.data(), bytes.size(), 3); }),
              "corrupt file: the vertex order section is not a permutation");
}

TEST(VertexOrderSection, OrdersThatFollowTheSurfaceCodeSmall) {
    // The identity costs next to nothing; runs of neighbours little; a
    // random order about log2(n) bits an index.
    const size_t n = 4096;
    std::vector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    const size_t identity = encodeVertexOrder(order).size();
    std::vector<uint32_t> local = order;
    for (size_t i = 0; i + 4 <= n; i += 4) std::reverse(local.begin() + long(i), local.begin() + long(i) + 4);
    const size_t runs = encodeVertexOrder(local).size();
    std::vector<uint32_t> random = order;
    std::shuffle(random.begin(), random.end(), std::mt19937(9));
    const size_t shuffled = encodeVertexOrder(random).size();
    EXPECT_LT(identity, n / 64);
    EXPECT_LT(identity, runs);
    EXPECT_LT(runs, n);  // under 2 bits an index
    EXPECT_GT(shuffled, n * 10 / 8);  // at least 10 of log2(4096) = 12 bits an index
    EXPECT_LT(shuffled, n * 16 / 8);
}

TEST(VertexOrderSection, WhatIsNotAPermutationIsCorrupt) {
    // Coded from lists that are not permutations: a repeat, an index past
    // the count.
    for (const std::vector<uint32_t>& bad : {std::vector<uint32_t>{0, 1, 1, 3}, std::vector<uint32_t>{0, 1, 2, 4}}) {
        const std::vector<uint8_t> bytes = encodeVertexOrder(bad);
        EXPECT_EQ(corruptionOf([&] { decodeVertexOrder(bytes.data(), bytes.size(), bad.size()); }),
                  "corrupt file: the vertex order section is not a permutation");
    }
    // A permutation of 4 read as one of 3 vertices: index 3 is past it.
    const std::vector<uint8_t> four = encodeVertexOrder({3, 2, 1, 0});
    EXPECT_NE(corruptionOf([&] { decodeVertexOrder(four.data(), four.size(), 3); }), "");
}

TEST(VertexOrderSection, TruncatedOrGarbageSectionsAreRefusedOrAPermutation) {
    std::vector<uint32_t> order(3000);
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), std::mt19937(3));
    const std::vector<uint8_t> bytes = encodeVertexOrder(order);
    for (size_t cut : {size_t(0), size_t(1), bytes.size() / 2, bytes.size() - 2}) {
        const std::string message = corruptionOf([&] { decodeVertexOrder(bytes.data(), cut, order.size()); });
        EXPECT_NE(message, "") << "cut at " << cut;
    }
    std::mt19937 rng(4);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<uint8_t> garbage(1 + rng() % 64);
        for (uint8_t& b : garbage) b = uint8_t(rng());
        const size_t n = 1 + rng() % 40;
        try {
            const std::vector<uint32_t> got = decodeVertexOrder(garbage.data(), garbage.size(), n);
            std::vector<uint32_t> sorted = got;
            std::sort(sorted.begin(), sorted.end());
            for (size_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i);  // whatever it reads is a permutation
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Corrupt) << e.what();
        }
    }
}

Mesh gridPatch(int n, int m) {  // an n x m grid of quads, each split in two
    Mesh mesh;
    for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= n; ++i) mesh.positions.insert(mesh.positions.end(), {float(i), float(j), 0.f});
    auto at = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i) {
            mesh.triangles.insert(mesh.triangles.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.insert(mesh.triangles.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

std::multiset<std::array<uint32_t, 3>> orientedTriangles(const Mesh& mesh) {
    std::multiset<std::array<uint32_t, 3>> set;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        std::array<uint32_t, 3> t = {mesh.triangles[3 * f], mesh.triangles[3 * f + 1], mesh.triangles[3 * f + 2]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        set.insert(t);
    }
    return set;
}

TEST(VertexOrder, KeepOrderGivesBackTheInputNumbering) {
    Mesh mesh = gridPatch(7, 5);
    mesh.positions.insert(mesh.positions.end(), {3.5f, 2.5f, 1.f});  // an isolated vertex
    EncodeOptions options;
    options.keepVertexOrder = true;
    const Encoded kept = encode(mesh, options);
    const Decoded decoded = decode(kept.bytes);
    const std::vector<int32_t> quantized = quantize(mesh.positions, makeGrid(mesh.positions, 12));
    EXPECT_EQ(decoded.quantized, quantized);
    EXPECT_EQ(orientedTriangles(decoded.mesh), orientedTriangles(mesh));
    EXPECT_GT(decoded.stats.vertexOrderBytes, 0u);
    for (size_t v = 0; v < kept.vertexOrder.size(); ++v) EXPECT_EQ(kept.vertexOrder[v], v);
    // Without the option, the tree order differs from the input order here,
    // and the file is smaller by exactly the order section and its framing.
    const Encoded plain = encode(mesh);
    EXPECT_LT(plain.bytes.size(), kept.bytes.size());
    EXPECT_EQ(plain.stats.vertexOrderBytes, 0u);
}

}  // namespace
}  // namespace drm
