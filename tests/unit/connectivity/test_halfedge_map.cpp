// HalfEdgeMap against std::map: inserts, look-ups of present and absent
// edges, growth, and rebuildKeeping (the traversal drops the edges between
// culled vertices with it), on random edges with many sharing an end vertex
// (as edges around one vertex do).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <utility>

#include "connectivity/halfedge_map.h"

namespace drm {
namespace {

// Half full at most (a table of the whole mesh) and a quarter full (the
// traversal's front).
TEST(HalfEdgeMap, AgreesWithStdMapThroughGrowthAndRebuilds) {
  for (size_t slotsPerEdge : {2, 4}) {
    SCOPED_TRACE(slotsPerEdge);
    std::mt19937 random(13);
    HalfEdgeMap table(4, slotsPerEdge);
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> truth;
    auto checkAll = [&](uint32_t range) {
        for (const auto& entry : truth) ASSERT_EQ(table.find(entry.first.first, entry.first.second), entry.second);
        for (int i = 0; i < 2000; ++i) {
            const uint32_t a = random() % range, b = random() % range;
            const auto it = truth.find({a, b});
            ASSERT_EQ(table.find(a, b), it == truth.end() ? HalfEdgeMap::kAbsent : it->second);
        }
        ASSERT_EQ(table.size(), truth.size());
        ASSERT_LE(slotsPerEdge * table.size(), table.capacity());
    };
    for (int round = 0; round < 6; ++round) {
        const uint32_t range = 64u << (2 * round);  // also vertices near 2^32 below
        for (int i = 0; i < 3000; ++i) {
            uint32_t a = random() % range, b = random() % 8;  // many edges into few vertices
            if (i % 3 == 0) std::swap(a, b);
            if (i % 7 == 0) a = 0xFFFFFFF0u + a % 8;
            if (a == b) continue;
            const uint32_t value = random() % 1000;
            const bool fresh = truth.emplace(std::make_pair(a, b), value).second;
            ASSERT_EQ(table.insert(a, b, value), fresh);
        }
        checkAll(range);
        // Drop the edges whose ends are both odd, as the traversal drops
        // those between culled vertices.
        auto keep = [&](uint32_t a, uint32_t b) { return a % 2 == 0 || b % 2 == 0 || round % 2 == 1; };
        table.rebuildKeeping([&](uint32_t a, uint32_t b, uint32_t) { return keep(a, b); });
        for (auto it = truth.begin(); it != truth.end();)
            it = keep(it->first.first, it->first.second) ? std::next(it) : truth.erase(it);
        ASSERT_LE(4 * slotsPerEdge * table.size(), std::max<size_t>(table.capacity(), 16));
        checkAll(range);
    }
  }
}

// The sweep asks keep() of every entry once, never of an empty slot.
TEST(HalfEdgeMap, RebuildAsksOfEntriesOnly) {
    HalfEdgeMap table(10, 4);
    for (uint32_t v = 1; v < 10; ++v) table.insert(v, v + 100, v);
    size_t asked = 0;
    table.rebuildKeeping([&](uint32_t a, uint32_t b, uint32_t) {
        EXPECT_TRUE(a >= 1 && a < 10 && b == a + 100) << a << " " << b;
        ++asked;
        return a % 3 == 0;
    });
    EXPECT_EQ(asked, 9u);
    EXPECT_EQ(table.size(), 3u);
    for (uint32_t v = 1; v < 10; ++v) EXPECT_EQ(table.find(v, v + 100), v % 3 == 0 ? v : HalfEdgeMap::kAbsent);
}

TEST(HalfEdgeMap, RebuildKeepingNothingEmptiesTheTable) {
    HalfEdgeMap table(100);
    for (uint32_t v = 1; v < 100; ++v) table.insert(0, v, v);
    table.rebuildKeeping([](uint32_t, uint32_t, uint32_t) { return false; });
    EXPECT_EQ(table.size(), 0u);
    EXPECT_EQ(table.capacity(), 256u);  // the least a rebuilt table keeps
    for (uint32_t v = 1; v < 100; ++v) EXPECT_EQ(table.find(0, v), HalfEdgeMap::kAbsent);
    EXPECT_TRUE(table.insert(0, 1, 7));
    EXPECT_EQ(table.find(0, 1), 7u);
}

// assign overwrites or inserts, erase makes an entry answer kAbsent, and a
// rebuild that drops kAbsent values frees their slots (the traversal's fan
// pieces come and go this way).
TEST(HalfEdgeMap, AssignEraseAndTheRebuildThatDropsErasedEntries) {
    std::mt19937 random(29);
    HalfEdgeMap table(4, 4);
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> truth;
    for (int round = 0; round < 8; ++round) {
        for (int i = 0; i < 4000; ++i) {
            const uint32_t a = random() % 300, b = random() % 300;
            if (a == b) continue;
            if (random() % 3 == 0) {
                table.erase(a, b);
                truth.erase({a, b});
            } else {
                const uint32_t value = random() % 1000;
                table.assign(a, b, value);
                truth[{a, b}] = value;
            }
        }
        for (uint32_t a = 0; a < 300; ++a)
            for (uint32_t b = 0; b < 300; ++b) {
                const auto it = truth.find({a, b});
                ASSERT_EQ(table.find(a, b), it == truth.end() ? HalfEdgeMap::kAbsent : it->second) << a << " " << b;
            }
        ASSERT_GE(table.size(), truth.size());  // erased entries hold their slots till a rebuild
        table.rebuildKeeping([](uint32_t, uint32_t, uint32_t value) { return value != HalfEdgeMap::kAbsent; });
        ASSERT_EQ(table.size(), truth.size());
    }
    // An erased edge may be inserted again, and growth drops erased entries.
    HalfEdgeMap again(4, 4);
    again.assign(5, 6, 1);
    again.erase(5, 6);
    EXPECT_TRUE(again.insert(5, 6, 2));
    EXPECT_EQ(again.find(5, 6), 2u);
    EXPECT_FALSE(again.insert(5, 6, 3));
    EXPECT_EQ(again.size(), 1u);
    HalfEdgeMap growing(2, 2);
    for (uint32_t v = 1; v <= 8; ++v) growing.assign(0, v, v);
    for (uint32_t v = 1; v <= 8; v += 2) growing.erase(0, v);
    for (uint32_t v = 9; v <= 40; ++v) growing.insert(0, v, v);  // grows past its first capacity
    for (uint32_t v = 1; v <= 40; ++v) EXPECT_EQ(growing.find(0, v), v <= 8 && v % 2 == 1 ? HalfEdgeMap::kAbsent : v) << v;
    EXPECT_EQ(growing.size(), 36u);
    table.erase(7, 8);  // absent: nothing happens
    table.erase(301, 302);
    EXPECT_EQ(table.size(), truth.size());
}

}  // namespace
}  // namespace drm
