// Octahedral coding of normals (attributes/octahedral.h): decoded grid
// points are unit vectors; the poles and the fold are where the definition
// puts them; the best of the neighbouring grid points is never farther
// than the nearest one and stays within maxNormalError (1.5 cells) at
// every bit depth; re-encoding a decoded direction finds that direction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "attributes/octahedral.h"
#include "drmcodec/drmcodec.h"

namespace drm {
namespace {

double angleBetween(const double a[3], const double b[3]) {
    const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

TEST(Octahedral, DecodedPointsAreUnitVectors) {
    for (int bits : {4, 10}) {
        const uint32_t top = (1u << bits) - 1;
        for (uint32_t a = 0; a <= top; a += (bits == 4 ? 1 : 7))
            for (uint32_t b = 0; b <= top; b += (bits == 4 ? 1 : 7)) {
                double n[3];
                octahedralDecode(a, b, bits, n);
                ASSERT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-12) << a << ", " << b;
            }
    }
}

TEST(Octahedral, PolesAndTheFold) {
    const int bits = 8;
    const uint32_t top = 255;
    uint32_t q[2];
    // The south pole folds onto the square's corners: (1, 1) of the square.
    octahedralEncode(0, 0, -1, bits, q);
    EXPECT_EQ(q[0], top);
    EXPECT_EQ(q[1], top);
    double n[3];
    octahedralDecode(top, top, bits, n);
    EXPECT_DOUBLE_EQ(n[0], 0);
    EXPECT_DOUBLE_EQ(n[1], 0);
    EXPECT_DOUBLE_EQ(n[2], -1);
    // Every corner of the square is the south pole.
    for (uint32_t a : {0u, top})
        for (uint32_t b : {0u, top}) {
            octahedralDecode(a, b, bits, n);
            EXPECT_DOUBLE_EQ(n[2], -1) << a << ", " << b;
        }
    // +x lies at the right edge's middle, +y at the top edge's.
    octahedralEncode(1, 0, 0, bits, q);
    EXPECT_EQ(q[0], top);
    EXPECT_EQ(q[1], (top + 1) / 2);
    octahedralEncode(0, 3, 0, bits, q);  // length does not matter
    EXPECT_EQ(q[0], (top + 1) / 2);
    EXPECT_EQ(q[1], top);
}

TEST(Octahedral, TheBestNeighbourIsNeverWorseAndWithinTheBound) {
    std::mt19937 rng(13);
    std::normal_distribution<double> gauss(0, 1);
    for (int bits = kMinNormalBits; bits <= kMaxNormalBits; ++bits) {
        double worstNearest = 0, worstBest = 0;
        for (int i = 0; i < 20000; ++i) {
            double d[3] = {gauss(rng), gauss(rng), gauss(rng)};
            if (i < 6) d[0] = d[1] = d[2] = 0, d[i % 3] = i < 3 ? 1 : -1;  // the axes
            uint32_t nearest[2], best[2];
            octahedralEncode(d[0], d[1], d[2], bits, nearest);
            octahedralEncodeBest(d[0], d[1], d[2], bits, best);
            ASSERT_LE(std::max(nearest[0], nearest[1]), (1u << bits) - 1);
            double a[3], b[3];
            octahedralDecode(nearest[0], nearest[1], bits, a);
            octahedralDecode(best[0], best[1], bits, b);
            const double errNearest = angleBetween(a, d), errBest = angleBetween(b, d);
            ASSERT_LE(errBest, errNearest + 1e-15);
            worstNearest = std::max(worstNearest, errNearest);
            worstBest = std::max(worstBest, errBest);
        }
        EXPECT_LE(worstBest, maxNormalError(bits)) << bits << " bits";
        EXPECT_LE(worstBest, worstNearest) << bits << " bits";
    }
}

TEST(Octahedral, ReencodingADecodedDirectionFindsIt) {
    const int bits = 6;
    const uint32_t top = (1u << bits) - 1;
    for (uint32_t a = 0; a <= top; ++a)
        for (uint32_t b = 0; b <= top; ++b) {
            double n[3], back[3];
            octahedralDecode(a, b, bits, n);
            uint32_t q[2];
            octahedralEncode(n[0], n[1], n[2], bits, q);
            octahedralDecode(q[0], q[1], bits, back);
            // The same grid point, or one on the fold that stands for the
            // same direction.
            ASSERT_LT(angleBetween(n, back), 1e-9) << a << ", " << b;
        }
}

}  // namespace
}  // namespace drm
