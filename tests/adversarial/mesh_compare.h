// Is a decoded mesh the input mesh, up to quantization? Checked from the
// promises of drmcodec.h alone, without the codec's own comparison:
//   - as many vertices and faces as the input;
//   - Encoded::vertexOrder is a permutation, decoded vertex i being input
//     vertex vertexOrder[i];
//   - every decoded vertex sits on the grid point drm::quantize gives its
//     input vertex, and within half a step of it;
//   - the faces, renumbered to input vertices, are the input's faces as a
//     multiset of oriented triangles (any starting corner, same orientation).
#ifndef DRM_TEST_ADVERSARIAL_MESH_COMPARE_H
#define DRM_TEST_ADVERSARIAL_MESH_COMPARE_H

#include <drmcodec/drmcodec.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace adversarial {

using Triangle = std::array<uint32_t, 3>;

// The lexicographically smallest rotation of t: the same triangle whatever
// corner it starts at, also when a corner repeats ((a, b, a) and (a, a, b)
// are one oriented triangle), while (a, c, b) stays different from (a, b, c).
inline Triangle canonicalTriangle(const Triangle& t) {
    Triangle best = t;
    for (int r = 1; r < 3; ++r) {
        const Triangle rotated = {t[r], t[(r + 1) % 3], t[(r + 2) % 3]};
        best = std::min(best, rotated);
    }
    return best;
}

// Oriented triangle -> how many faces are that triangle. With renumber,
// each index i is replaced by renumber[i] first.
inline std::map<Triangle, int> triangleCounts(const std::vector<uint32_t>& corners,
                                              const std::vector<uint32_t>* renumber = nullptr) {
    std::map<Triangle, int> counts;
    for (size_t c = 0; c + 2 < corners.size(); c += 3) {
        Triangle t = {corners[c], corners[c + 1], corners[c + 2]};
        if (renumber)
            for (uint32_t& v : t) v = (*renumber)[v];
        ++counts[canonicalTriangle(t)];
    }
    return counts;
}

inline bool repeatsAnIndex(uint32_t a, uint32_t b, uint32_t c) { return a == b || b == c || a == c; }

inline bool isPermutation(const std::vector<uint32_t>& order, size_t n) {
    if (order.size() != n) return false;
    std::vector<bool> seen(n, false);
    for (uint32_t v : order) {
        if (v >= n || seen[v]) return false;
        seen[v] = true;
    }
    return true;
}

// The first few triangles whose counts differ, for a failure message.
inline std::string describeTriangleDifference(const std::map<Triangle, int>& input,
                                              const std::map<Triangle, int>& decoded) {
    std::map<Triangle, int> difference = input;  // input count - decoded count
    for (const auto& entry : decoded) difference[entry.first] -= entry.second;
    std::ostringstream out;
    int shown = 0, differing = 0;
    for (const auto& entry : difference) {
        if (entry.second == 0) continue;
        ++differing;
        if (shown++ < 6)
            out << "\n  (" << entry.first[0] << ", " << entry.first[1] << ", " << entry.first[2] << "): "
                << (entry.second > 0 ? "missing " : "extra ") << std::abs(entry.second);
    }
    return std::to_string(differing) + " oriented triangles differ (input indices):" + out.str();
}

// Success if `decoded` is `input` up to quantization to `bits` bits, as
// described at the top of this file; otherwise what differs.
inline ::testing::AssertionResult isLosslessRoundTrip(const drm::Mesh& input, int bits, const drm::Encoded& encoded,
                                                      const drm::Decoded& decoded) {
    const size_t vertexCount = input.vertexCount();
    const drm::Mesh& out = decoded.mesh;
    if (out.vertexCount() != vertexCount || decoded.quantized.size() != 3 * vertexCount)
        return ::testing::AssertionFailure() << "decoded " << out.vertexCount() << " vertices ("
                                             << decoded.quantized.size() << " grid coordinates), input has "
                                             << vertexCount;
    if (out.faceCount() != input.faceCount() || out.triangles.size() % 3 != 0)
        return ::testing::AssertionFailure() << "decoded " << out.faceCount() << " faces, input has "
                                             << input.faceCount();
    if (decoded.stats.vertices != vertexCount || decoded.stats.faces != input.faceCount())
        return ::testing::AssertionFailure() << "decoded stats count " << decoded.stats.vertices << " vertices and "
                                             << decoded.stats.faces << " faces";
    if (!isPermutation(encoded.vertexOrder, vertexCount))
        return ::testing::AssertionFailure() << "Encoded::vertexOrder is not a permutation of the "
                                             << vertexCount << " input vertices";

    const drm::Grid grid = drm::makeGrid(input.positions, bits);
    const std::vector<int32_t> expected = drm::quantize(input.positions, grid);
    double largest = 0;
    for (float x : input.positions) largest = std::max(largest, double(std::fabs(x)));
    // origin + q * step, rounded to float: within half a step of the input.
    const double tolerance = 0.5 * grid.step + 4.0 * FLT_EPSILON * (largest + grid.step * (1 << bits));
    for (size_t i = 0; i < vertexCount; ++i) {
        const size_t original = encoded.vertexOrder[i];
        for (int k = 0; k < 3; ++k) {
            if (decoded.quantized[3 * i + k] != expected[3 * original + k])
                return ::testing::AssertionFailure()
                       << "decoded vertex " << i << " (input vertex " << original << ") has grid coordinate "
                       << decoded.quantized[3 * i + k] << " on axis " << k << ", expected " << expected[3 * original + k];
            const double error = std::fabs(double(out.positions[3 * i + k]) - double(input.positions[3 * original + k]));
            if (!(error <= tolerance))
                return ::testing::AssertionFailure() << "decoded vertex " << i << " is " << error
                                                     << " from input vertex " << original << " on axis " << k
                                                     << " (half a step is " << 0.5 * grid.step << ")";
        }
    }

    for (size_t c = 0; c < out.triangles.size(); ++c)
        if (out.triangles[c] >= vertexCount)
            return ::testing::AssertionFailure() << "decoded face " << c / 3 << " refers to vertex "
                                                 << out.triangles[c] << " of " << vertexCount;
    const auto before = triangleCounts(input.triangles);
    const auto after = triangleCounts(out.triangles, &encoded.vertexOrder);
    if (before != after) return ::testing::AssertionFailure() << describeTriangleDifference(before, after);
    return ::testing::AssertionSuccess();
}

}  // namespace adversarial

#endif  // DRM_TEST_ADVERSARIAL_MESH_COMPARE_H
