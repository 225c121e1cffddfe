// The tree coder's residual models (geometry/tree/residual_model.h): a
// residual's bit length without a branch is its bit length; codeResidual
// through a Writer and a Reader gives back every residual of 21-bit
// coordinates, asking the sign model by the residual's length; and
// ResidualCosts prices each length by the definition in the header (zero
// flag, unary length, one bit for the sign and each bit below the leading
// one): 2n + 1 bits on models that know nothing yet, and after learning
// what fresh prices over the same models say.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "common.h"
#include "entropy/bit_model.h"
#include "entropy/range_coder.h"
#include "geometry/tree/residual_model.h"

namespace drm {
namespace {

TEST(ResidualModel, LengthOfIsTheBitLengthOfTheMagnitude) {
    for (int32_t v : {0, 1, -1, 2, -2, 3, 1000, -1000, (1 << 21) - 1, -(1 << 22), std::numeric_limits<int32_t>::max(),
                      std::numeric_limits<int32_t>::min()}) {
        const uint64_t magnitude = v < 0 ? uint64_t(-int64_t(v)) : uint64_t(v);
        EXPECT_EQ(magnitudeOf(v), magnitude) << v;
        EXPECT_EQ(lengthOf(v), bitLength(magnitude)) << v;
    }
}

TEST(ResidualModel, EveryResidualRoundTrips) {
    std::mt19937 rng(12);
    std::vector<int32_t> residuals = {0, 1, -1, 2, -2, 3, -3, 4, (1 << 21) - 1, -((1 << 21) - 1), (1 << 22) - 1,
                                      -((1 << 22) - 1)};
    for (int i = 0; i < 5000; ++i) {
        const int length = int(rng() % 23);
        const int32_t magnitude = length == 0 ? 0 : int32_t((1u << (length - 1)) | (rng() & ((1u << (length - 1)) - 1)));
        residuals.push_back(rng() % 2 ? magnitude : -magnitude);
    }
    std::vector<int> signLengths;
    AxisModels encoding[2];
    encoding[1].makeAgile();
    std::vector<uint8_t> bytes[2];
    for (int agile = 0; agile < 2; ++agile) {
        RangeEncoder coder;
        Writer writer{coder};
        for (size_t i = 0; i < residuals.size(); ++i) {
            AxisModels& m = encoding[agile];
            const int context = int(i % kMagnitudeContexts);
            const int32_t coded = codeResidual(writer, m, context, [&](int length) -> BitModel& {
                if (agile == 0) signLengths.push_back(length);
                return m.sign[length % kSignContexts];
            }, residuals[i]);
            ASSERT_EQ(coded, residuals[i]);  // the writer gives back what it codes
        }
        bytes[agile] = coder.finish();
    }
    // The sign is asked for each non-zero residual, with its bit length.
    std::vector<int> expectedLengths;
    for (int32_t r : residuals)
        if (r != 0) expectedLengths.push_back(lengthOf(r));
    EXPECT_EQ(signLengths, expectedLengths);
    for (int agile = 0; agile < 2; ++agile) {
        AxisModels m;
        if (agile) m.makeAgile();
        RangeDecoder coder(bytes[agile].data(), bytes[agile].size());
        Reader reader{coder};
        for (size_t i = 0; i < residuals.size(); ++i) {
            const int context = int(i % kMagnitudeContexts);
            const int32_t decoded =
                codeResidual(reader, m, context, [&](int length) -> BitModel& { return m.sign[length % kSignContexts]; }, 0);
            ASSERT_EQ(decoded, residuals[i]) << "residual " << i << (agile ? ", agile models" : "");
        }
    }
}

TEST(ResidualModel, FreshModelsPriceALengthOfNAt2NPlus1Bits) {
    // Every model at P(1) = 1/2: each coded bit costs exactly one.
    const AxisModels m;
    const ResidualCosts costs(m, 3);
    EXPECT_DOUBLE_EQ(costs(0), 1.0);  // the zero flag
    for (int n = 1; n < kMaxLength; ++n) {
        const int32_t r = int32_t(1) << (n - 1);
        // zero flag, n - 1 "longer", one "not longer", the sign, n - 1 bits.
        EXPECT_DOUBLE_EQ(costs(r), 2.0 * n + 1) << n;
        EXPECT_DOUBLE_EQ(costs(-r), 2.0 * n + 1) << n;
    }
    // The longest length has no "not longer" flag.
    EXPECT_DOUBLE_EQ(costs(int32_t(1) << (kMaxLength - 1)), 2.0 * kMaxLength);
    const double* table = costs.upTo(5);
    for (int n = 0; n <= 5; ++n) EXPECT_DOUBLE_EQ(table[n], n == 0 ? 1.0 : 2.0 * n + 1);
}

TEST(ResidualModel, PricesFollowTheModelsOnceForgotten) {
    AxisModels m;
    ResidualCosts costs(m, 0);
    const double before = costs(5);
    // Models that have seen only zeros: a zero gets cheap, anything else dear.
    for (int i = 0; i < 200; ++i) m.zero[0].observe(1);
    costs.forget();
    const ResidualCosts fresh(m, 0);
    EXPECT_LT(costs(0), 0.1);
    EXPECT_GT(costs(5), before);
    for (int32_t r : {0, 1, -7, 100, 4000}) EXPECT_DOUBLE_EQ(costs(r), fresh(r)) << r;
    // By the definition: the zero flag's own cost, then one bit each.
    EXPECT_DOUBLE_EQ(costs(1), m.zero[0].cost(0) + 1 + m.longer[0][1].cost(0));
    EXPECT_DOUBLE_EQ(costs(2), m.zero[0].cost(0) + 1 + 1 + m.longer[0][1].cost(1) + m.longer[0][2].cost(0));
}

}  // namespace
}  // namespace drm
