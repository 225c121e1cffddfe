// The adaptive binary model: the agile start (the spanning-tree vertex
// coder's) against the fixed rates every other coder keeps.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "entropy/bit_model.h"
#include "entropy/range_coder.h"

namespace drm {
namespace {

// While young, an agile model's estimate is the plain average of its start
// and the bits seen: from 1/2, after seven zeros P(1) = 1/16 exactly, so a
// one costs 4 bits. A model with the fixed rates has not come that far.
TEST(BitModel, AnAgileModelAveragesItsFirstBits) {
    BitModel agile = BitModel::agile(), fixed;
    for (int i = 0; i < 7; ++i) {
        agile.observe(0);
        fixed.observe(0);
    }
    EXPECT_DOUBLE_EQ(agile.cost(1), 4.0);
    EXPECT_LT(fixed.cost(1), 3.0);
    EXPECT_GT(fixed.cost(1), 1.0);
}

// Once its rates have slowed to the fixed ones it keeps them: after the same
// long run of bits the two models give the same estimates within rounding,
// and they keep moving together.
TEST(BitModel, AnAgileModelSettlesOnTheFixedRates) {
    std::mt19937 rng(5);
    BitModel agile = BitModel::agile(), fixed;
    for (int i = 0; i < 4000; ++i) {
        const int bit = rng() % 10 == 0;
        agile.observe(bit);
        fixed.observe(bit);
    }
    EXPECT_NEAR(agile.cost(1), fixed.cost(1), 0.01);
    EXPECT_NEAR(agile.cost(0), fixed.cost(0), 0.01);
}

// Coded and decoded through the range coder, agile models give back the
// bits, and code a skewed source in fewer bytes than fixed ones when the
// source is short.
TEST(BitModel, AgileModelsRoundTripAndLearnShortSourcesCheaper) {
    std::mt19937 rng(9);
    std::vector<int> bits(300);
    for (int& b : bits) b = rng() % 20 == 0;
    auto encode = [&](BitModel model) {
        RangeEncoder coder;
        for (int b : bits) model.encode(coder, b);
        return coder.finish();
    };
    const std::vector<uint8_t> agileBytes = encode(BitModel::agile()), fixedBytes = encode(BitModel());
    EXPECT_LT(agileBytes.size(), fixedBytes.size());
    RangeDecoder decoder(agileBytes.data(), agileBytes.size());
    BitModel model = BitModel::agile();
    for (size_t i = 0; i < bits.size(); ++i) ASSERT_EQ(model.decode(decoder), bits[i]) << "bit " << i;
}

}  // namespace
}  // namespace drm
