// front_ranks.h against a brute force: every admissible candidate sorted by
// (squared distance, id). Random fronts with many equal distances
// (coincident points, points on a small lattice), random admissibility and
// skipped ids; every rank from 0 past the last, so that the one-pass path,
// both of its ways to the fallback (a rank too large for the kept array,
// too few admissible among the nearest) and a corrupt rank are all taken.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "connectivity/topological/front_ranks.h"

namespace drm {
namespace {

TEST(FrontRanks, AgreeWithSortingEveryAdmissibleCandidate) {
    std::mt19937 random(71);
    std::vector<RankKey> scratch;
    size_t fallbacks = 0, fastPaths = 0;
    for (int round = 0; round < 300; ++round) {
        const size_t n = 1 + random() % (round % 3 == 0 ? 400 : 60);  // blocks of kFrontBlock, and a part of one
        const int spread = 1 + int(random() % (round % 2 == 0 ? 3 : 1000));  // 1..3: a crowded lattice, many ties
        std::vector<int32_t> positions(3 * n);
        std::vector<uint32_t> ids(n);
        std::vector<uint8_t> admissibleId(4 * n + 8);
        for (size_t k = 0; k < n; ++k) {
            for (int a = 0; a < 3; ++a) positions[3 * k + size_t(a)] = int32_t(random() % uint32_t(spread)) + 2000;
            ids[k] = uint32_t(k * 4 + random() % 4);  // distinct, unordered gaps
        }
        std::shuffle(ids.begin(), ids.end(), random);
        const int admitPercent = int(random() % 100);
        for (uint8_t& a : admissibleId) a = int(random() % 100) < admitPercent;
        auto admissible = [&](uint32_t v) { return admissibleId[v] != 0; };
        const uint32_t skipA = ids[random() % n], skipB = random() % 2 ? ids[random() % n] : kNoVertex;
        const int64_t p[3] = {2000 + int64_t(random() % uint32_t(spread + 2)) - 1, 2000, 2000 + int64_t(random() % 5)};
        std::vector<RankKey> truth;
        for (size_t k = 0; k < n; ++k) {
            if (ids[k] == skipA || ids[k] == skipB || !admissible(ids[k])) continue;
            int64_t d2 = 0;
            for (int a = 0; a < 3; ++a) {
                const int64_t d = positions[3 * k + size_t(a)] - p[a];
                d2 += d * d;
            }
            truth.emplace_back(d2, ids[k]);
        }
        std::sort(truth.begin(), truth.end());
        std::vector<double> axes[3];
        for (size_t k = 0; k < n; ++k)
            for (int a = 0; a < 3; ++a) axes[a].push_back(double(positions[3 * k + size_t(a)]));
        const FrontView front{axes[0].data(), axes[1].data(), axes[2].data(), ids.data(), n};
        for (uint32_t rank = 0; rank < truth.size() + 3; ++rank) {
            const uint32_t found = frontVertexOfRank(front, p, skipA, skipB, rank, admissible, scratch);
            ASSERT_EQ(found, rank < truth.size() ? truth[rank].second : kNoVertex) << "round " << round << " rank " << rank;
            (rank + 8 <= kNearestKept ? fastPaths : fallbacks) += 1;
        }
        for (uint32_t rank = 0; rank < truth.size(); ++rank)
            ASSERT_EQ(rankAmongFront(front, p, skipA, skipB, truth[rank], admissible, scratch), rank) << "round " << round;
        ASSERT_EQ(frontVertexOfRank(front, p, skipA, skipB, 0xFFFFFFFFu, admissible, scratch), kNoVertex);  // a negative rank read
    }
    EXPECT_GT(fastPaths, 1000u);
    EXPECT_GT(fallbacks, 1000u);
}

}  // namespace
}  // namespace drm
