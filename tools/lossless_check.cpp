// findLosslessMismatch: see lossless_check.h.
#include "lossless_check.h"

#include <algorithm>
#include <array>
#include <vector>

namespace drm {
namespace cli {

namespace {

using Triangle = std::array<uint32_t, 3>;

// The smallest of the three rotations of (a, b, c): the same oriented
// triangle whichever corner a file lists first (also for faces such as
// (a, a, b), where "start at the smallest index" is ambiguous).
Triangle canonicalRotation(uint32_t a, uint32_t b, uint32_t c) {
    return std::min({Triangle{a, b, c}, Triangle{b, c, a}, Triangle{c, a, b}});
}

std::string describe(const Triangle& t) {
    return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

}  // namespace

std::string findLosslessMismatch(const drm::Mesh& input, const drm::Encoded& encoded, const drm::Decoded& decoded) {
    const size_t vertexCount = input.vertexCount();
    if (decoded.mesh.vertexCount() != vertexCount)
        return "decoded " + std::to_string(decoded.mesh.vertexCount()) + " vertices, the input has " +
               std::to_string(vertexCount);
    if (encoded.vertexOrder.size() != vertexCount || encoded.quantized.size() != 3 * vertexCount ||
        decoded.quantized.size() != 3 * vertexCount)
        return "the encoder's vertex order or quantized positions do not cover every vertex";
    std::vector<bool> seen(vertexCount, false);
    for (uint32_t original : encoded.vertexOrder) {
        if (original >= vertexCount || seen[original]) return "the encoder's vertex order is not a permutation";
        seen[original] = true;
    }
    for (size_t i = 0; i < vertexCount; ++i) {
        const uint32_t original = encoded.vertexOrder[i];
        for (int k = 0; k < 3; ++k) {
            if (decoded.quantized[3 * i + k] != encoded.quantized[3 * size_t(original) + k])
                return "decoded vertex " + std::to_string(i) + " (input vertex " + std::to_string(original) +
                       ") sits at another grid point than the input's";
        }
    }

    if (decoded.mesh.faceCount() != input.faceCount())
        return "decoded " + std::to_string(decoded.mesh.faceCount()) + " faces, the input has " +
               std::to_string(input.faceCount());
    std::vector<Triangle> inputFaces, decodedFaces;
    inputFaces.reserve(input.faceCount());
    decodedFaces.reserve(input.faceCount());
    for (size_t f = 0; f < input.faceCount(); ++f) {
        const uint32_t* t = &input.triangles[3 * f];
        inputFaces.push_back(canonicalRotation(t[0], t[1], t[2]));
        const uint32_t* d = &decoded.mesh.triangles[3 * f];
        for (int k = 0; k < 3; ++k)
            if (d[k] >= vertexCount) return "decoded face " + std::to_string(f) + " refers to a missing vertex";
        decodedFaces.push_back(canonicalRotation(encoded.vertexOrder[d[0]], encoded.vertexOrder[d[1]],
                                                 encoded.vertexOrder[d[2]]));
    }
    std::sort(inputFaces.begin(), inputFaces.end());
    std::sort(decodedFaces.begin(), decodedFaces.end());
    const auto difference = std::mismatch(inputFaces.begin(), inputFaces.end(), decodedFaces.begin());
    if (difference.first != inputFaces.end()) {
        const Triangle& first = std::min(*difference.first, *difference.second);
        auto countOf = [&first](const std::vector<Triangle>& sorted) {
            const auto range = std::equal_range(sorted.begin(), sorted.end(), first);
            return std::to_string(range.second - range.first);
        };
        return "triangle " + describe(first) + " (input vertex indices) appears " + countOf(inputFaces) +
               " times in the input and " + countOf(decodedFaces) + " times in the decoded mesh";
    }
    return "";
}

}  // namespace cli
}  // namespace drm
