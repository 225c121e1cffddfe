// The tree encoder's prices (geometry/tree/tree_pricing.h) against their
// definitions: a residual costs the residual models' price of each axis
// (the parent's group for candidate 0, the others' for the rest), every
// candidate's at once as each alone; naming a candidate costs the "no"
// flags before it and its own "yes" (a repeat is never named, the last
// needs no flag), or one symbol's share of its table; and the pick is the
// cheapest sum, ties to the first vertex, then its first candidate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "geometry/tree/tree_pricing.h"

namespace drm {
namespace tree_coding {
namespace {

// A state over a patch of points, with models that have seen some bits,
// and the predictions for a child of `parent`.
struct PricedState {
    CodingState s;
    Predictions p;
    int contexts[kResidualGroups][3];
    PricedState(bool flags, uint32_t parent) : s(3, flags, false) {
        for (uint32_t v = 0; v < 30; ++v) {
            s.begin(v == 0 ? kNoVertex : v - 1);
            s.place(v, GridPoint{int32_t(40 + (v % 6) * 5), int32_t(40 + (v / 6) * 4), int32_t(40 + v % 3)});
        }
        std::mt19937 rng(18);
        for (int i = 0; i < 300; ++i) {  // the models learn something
            s.axis[i % 2][i % 3].zero[i % kMagnitudeContexts].observe(rng() % 3 == 0);
            s.axis[i % 2][i % 3].longer[i % kMagnitudeContexts][1 + i % 4].observe(rng() % 2);
            s.isChoice[i % 4][i % kDistanceBuckets][0][i % 2].observe(rng() % 5 == 0);
        }
        p = predict(s, 30, parent);
        for (int g = 0; g < kResidualGroups; ++g)
            for (int a = 0; a < 3; ++a) contexts[g][a] = (g + a) % kMagnitudeContexts;
    }
};

double residualByDefinition(CodingState& s, const int (*contexts)[3], GridPoint r, uint32_t c) {
    const int g = residualGroup(c);
    const ResidualCosts x(s.axis[g][0], contexts[g][0]), y(s.axis[g][1], contexts[g][1]), z(s.axis[g][2], contexts[g][2]);
    return x(r.x) + y(r.y) + z(r.z);
}

TEST(TreePricing, ResidualsCostWhatTheModelsSay) {
    PricedState t(true, 12);
    const Pricing price(t.s, t.p, t.contexts);
    const GridPoint actual{57, 50, 41};
    double residual[kMaxCandidates], leastFrom[kMaxCandidates + 1];
    price.residuals(actual, residual, leastFrom);
    ASSERT_GT(t.p.count, 4);
    for (int c = 0; c < t.p.count; ++c) {
        const double expected = residualByDefinition(t.s, t.contexts, actual - t.p.candidate(c), uint32_t(c));
        EXPECT_DOUBLE_EQ(price.residual(actual - t.p.candidate(c), uint32_t(c)), expected) << c;
        EXPECT_DOUBLE_EQ(residual[c], expected) << c;
    }
    EXPECT_EQ(leastFrom[t.p.count], 1e300);
    for (int c = t.p.count - 1; c >= 0; --c) EXPECT_EQ(leastFrom[c], std::min(residual[c], leastFrom[c + 1])) << c;
}

TEST(TreePricing, NamingACandidateWithFlagsOrASymbol) {
    PricedState flags(true, 12);
    const Pricing withFlags(flags.s, flags.p, flags.contexts);
    double no = 0;
    for (int c = 0; c < flags.p.count; ++c) {
        EXPECT_DOUBLE_EQ(withFlags.choiceFloor(c), c == 0 ? 0.0 : no) << c;
        if (repeatsEarlier(flags.p, c)) {
            EXPECT_EQ(withFlags.choice(c), 1e300) << c;  // an equal candidate comes first
            continue;
        }
        const BitModel& flag = flagOf(flags.s, flags.p, c);
        if (nextFlagged(flags.p, c) == flags.p.count) {
            EXPECT_DOUBLE_EQ(withFlags.choice(c), no) << c;  // the last: named by the "no"s alone
        } else {
            EXPECT_DOUBLE_EQ(withFlags.choice(c), no + flag.cost(1)) << c;
            no += flag.cost(0);
        }
    }
    PricedState symbol(false, 12);
    const Pricing withSymbol(symbol.s, symbol.p, symbol.contexts);
    const AdaptiveFrequencies& table = symbol.s.predictorChoice[std::min<uint32_t>(symbol.s.previousChoice, kChoiceContexts - 1)];
    for (int c = 0; c < symbol.p.count; ++c) {
        EXPECT_DOUBLE_EQ(withSymbol.choice(c), std::log2(double(table.totalCount()) / table.countOf(uint32_t(c))));
        EXPECT_EQ(withSymbol.choiceFloor(c), 0.0);
    }
}

TEST(TreePricing, ThePickIsTheCheapestTheFirstOfEquals) {
    for (bool flags : {true, false}) {
        for (uint32_t parent : {3u, 12u, 20u}) {
            PricedState t(flags, parent);
            const Pricing price(t.s, t.p, t.contexts);
            std::mt19937 rng(parent);
            std::vector<GridPoint> next;
            for (int i = 0; i < 6; ++i)
                next.push_back(t.p.candidate(int(rng() % uint32_t(t.p.count))) + GridPoint{int32_t(rng() % 5) - 2, int32_t(rng() % 3) - 1, 0});
            next.push_back(next[2]);  // a tie between vertices 2 and 6
            Pick expected;
            for (int i = 0; i < int(next.size()); ++i)
                for (int c = 0; c < t.p.count; ++c) {
                    const double cost = price.residual(next[size_t(i)] - t.p.candidate(c), uint32_t(c)) + price.choice(c);
                    if (cost < expected.bits) expected = {uint32_t(c), cost, i};
                }
            const Pick got = cheapestPick(price, t.p, int(next.size()), [&](int i) { return next[size_t(i)]; });
            EXPECT_EQ(got.vertex, expected.vertex);
            EXPECT_EQ(got.candidate, expected.candidate);
            EXPECT_DOUBLE_EQ(got.bits, expected.bits);
            EXPECT_NE(got.vertex, 6) << "of equal vertices, the first";
            // One vertex alone: its cheapest candidate.
            const Pick one = bestPrediction(price, t.p, next[0]);
            Pick alone;
            for (int c = 0; c < t.p.count; ++c) {
                const double cost = price.residual(next[0] - t.p.candidate(c), uint32_t(c)) + price.choice(c);
                if (cost < alone.bits) alone = {uint32_t(c), cost, 0};
            }
            EXPECT_EQ(one.candidate, alone.candidate);
            EXPECT_DOUBLE_EQ(one.bits, alone.bits);
        }
    }
}

}  // namespace
}  // namespace tree_coding
}  // namespace drm
