// findLosslessMismatch: see lossless_check.h.
#include "lossless_check.h"

#include "cli.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
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

// Faces and corners of the decoded mesh against the input's, through
// faceOrder and faceRotation: decoded corner k of face i is corner
// (faceRotation[i] + k) % 3 of input face faceOrder[i].
std::string checkFaceOrder(const drm::Mesh& input, const drm::Encoded& encoded, const drm::Decoded& decoded) {
    const size_t faces = input.faceCount();
    if (decoded.mesh.faceCount() != faces)
        return "decoded " + std::to_string(decoded.mesh.faceCount()) + " faces, the input has " + std::to_string(faces);
    if (encoded.faceOrder.size() != faces || encoded.faceRotation.size() != faces)
        return "the encoder gives no face order (Encoded::faceOrder) to compare faces and corners by";
    std::vector<bool> seen(faces, false);
    for (size_t i = 0; i < faces; ++i) {
        const uint32_t f = encoded.faceOrder[i];
        if (f >= faces || seen[f] || encoded.faceRotation[i] > 2) return "the encoder's face order is not a permutation";
        seen[f] = true;
        for (int k = 0; k < 3; ++k)
            if (decoded.mesh.triangles[3 * i + size_t(k)] >= decoded.mesh.vertexCount())
                return "decoded face " + std::to_string(i) + " refers to a missing vertex";
    }
    return "";
}

size_t inputCorner(const drm::Encoded& encoded, size_t decodedFace, int k) {
    return 3 * size_t(encoded.faceOrder[decodedFace]) + size_t((encoded.faceRotation[decodedFace] + k) % 3);
}

std::string findWeldedMismatch(const drm::Mesh& input, const drm::Encoded& encoded, const drm::Decoded& decoded) {
    const std::string order = checkFaceOrder(input, encoded, decoded);
    if (!order.empty()) return order;
    if (encoded.quantized.size() != 3 * input.vertexCount() || decoded.quantized.size() != 3 * decoded.mesh.vertexCount())
        return "the quantized positions do not cover every vertex";
    for (size_t i = 0; i < input.faceCount(); ++i)
        for (int k = 0; k < 3; ++k) {
            const size_t corner = inputCorner(encoded, i, k);
            const uint32_t original = input.triangles[corner];
            const uint32_t now = decoded.mesh.triangles[3 * i + size_t(k)];
            for (int a = 0; a < 3; ++a)
                if (decoded.quantized[3 * size_t(now) + size_t(a)] != encoded.quantized[3 * size_t(original) + size_t(a)])
                    return "corner " + std::to_string(corner % 3) + " of input face " + std::to_string(corner / 3) +
                           " (input vertex " + std::to_string(original) + ") sits at another grid point after welding";
        }
    return "";
}

// One attribute's value at a corner, from a per-vertex or a per-corner array.
struct CornerValues {
    const std::vector<float>* perVertex = nullptr;
    const std::vector<float>* perCorner = nullptr;
    const std::vector<uint32_t>* triangles = nullptr;
    size_t width = 0;
    const float* at(size_t corner) const {
        if (perCorner && !perCorner->empty()) return &(*perCorner)[width * corner];
        if (perVertex && !perVertex->empty()) return &(*perVertex)[width * size_t((*triangles)[corner])];
        return nullptr;
    }
    bool present() const { return (perCorner && !perCorner->empty()) || (perVertex && !perVertex->empty()); }
};

std::string cornerName(size_t corner) {
    return "corner " + std::to_string(corner % 3) + " of input face " + std::to_string(corner / 3);
}

double angleDegrees(const float* a, const float* b) {
    double dot = 0, la = 0, lb = 0;
    for (int k = 0; k < 3; ++k) {
        dot += double(a[k]) * double(b[k]);
        la += double(a[k]) * double(a[k]);
        lb += double(b[k]) * double(b[k]);
    }
    if (la == 0 || lb == 0) return la == lb ? 0.0 : 180.0;
    const double c = std::max(-1.0, std::min(1.0, dot / std::sqrt(la * lb)));
    return std::acos(c) * 180.0 / 3.14159265358979323846;
}

// Half a step of the grid drmcodec.h describes: 2^bits - 1 steps across the
// wider axis of the values' range.
double halfStep(const std::vector<float>& values, int bits) {
    if (values.empty()) return 0;
    float low[2] = {values[0], values[1]}, high[2] = {values[0], values[1]};
    for (size_t i = 0; i < values.size(); i += 2)
        for (int a = 0; a < 2; ++a) {
            low[a] = std::min(low[a], values[i + size_t(a)]);
            high[a] = std::max(high[a], values[i + size_t(a)]);
        }
    const double range = std::max(double(high[0]) - double(low[0]), double(high[1]) - double(low[1]));
    return 0.5 * range / (std::ldexp(1.0, bits) - 1.0);
}

template <class T>
std::string comparePerVertexExact(const std::vector<T>& in, const std::vector<T>& out, size_t width,
                                  const drm::Mesh& input, const drm::Encoded& encoded, const drm::Decoded& decoded,
                                  const char* what) {
    if (out.size() != width * decoded.mesh.vertexCount()) return std::string("the decoded mesh has no ") + what;
    for (size_t i = 0; i < input.faceCount(); ++i)
        for (int k = 0; k < 3; ++k) {
            const size_t corner = inputCorner(encoded, i, k);
            const T* a = &in[width * size_t(input.triangles[corner])];
            const T* b = &out[width * size_t(decoded.mesh.triangles[3 * i + size_t(k)])];
            if (std::memcmp(a, b, width * sizeof(T)) != 0)
                return std::string("the ") + what + " at " + cornerName(corner) + " (input vertex " +
                       std::to_string(input.triangles[corner]) + ") changed";
        }
    return "";
}

template <class T>
std::string comparePerFaceExact(const std::vector<T>& in, const std::vector<T>& out, size_t width,
                                const drm::Encoded& encoded, const char* what) {
    if (out.size() != in.size()) return std::string("the decoded mesh has no ") + what;
    for (size_t i = 0; i < encoded.faceOrder.size(); ++i)
        if (std::memcmp(&in[width * size_t(encoded.faceOrder[i])], &out[width * i], width * sizeof(T)) != 0)
            return std::string("the ") + what + " of input face " + std::to_string(encoded.faceOrder[i]) + " changed";
    return "";
}

}  // namespace

double normalAngleBound(int normalBits) { return 0.2 * std::ldexp(1.0, std::max(0, 10 - normalBits)); }

std::string findAttributeMismatch(const drm::Mesh& input, const drm::EncodeOptions& options,
                                  const drm::Encoded& encoded, const drm::Decoded& decoded) {
    const uint32_t wanted = drm::attributesOf(input) & options.attributes;
    if (wanted == 0) return "";
    const std::string order = checkFaceOrder(input, encoded, decoded);
    if (!order.empty()) return order;
    const drm::Mesh& out = decoded.mesh;
    std::string problem;
    if (wanted & drm::kAttrColors) problem = comparePerVertexExact(input.colors, out.colors, 4, input, encoded, decoded, "vertex colour");
    if (problem.empty() && (wanted & drm::kAttrQuality))
        problem = comparePerVertexExact(input.quality, out.quality, 1, input, encoded, decoded, "vertex quality");
    if (problem.empty() && (wanted & drm::kAttrFaceColors))
        problem = comparePerFaceExact(input.faceColors, out.faceColors, 4, encoded, "face colour");
    if (problem.empty() && (wanted & drm::kAttrFaceQuality))
        problem = comparePerFaceExact(input.faceQuality, out.faceQuality, 1, encoded, "face quality");
    if (problem.empty() && (wanted & drm::kAttrFaceMaterial) && !input.faceMaterial.empty())
        problem = comparePerFaceExact(input.faceMaterial, out.faceMaterial, 1, encoded, "material");
    if (problem.empty() && (wanted & drm::kAttrFaceTexture) && !input.faceTexture.empty())
        problem = comparePerFaceExact(input.faceTexture, out.faceTexture, 1, encoded, "texture index");
    if (!problem.empty()) return problem;
    if ((wanted & drm::kAttrFaceMaterial) && out.materials != input.materials) return "the material names changed";
    if ((wanted & drm::kAttrFaceTexture) && out.textures != input.textures) return "the texture file names changed";
    if ((wanted & drm::kAttrMetadata) && out.metadata != input.metadata) return "the metadata changed";

    const bool normals = wanted & (drm::kAttrNormals | drm::kAttrCornerNormals);
    const bool texCoords = wanted & (drm::kAttrTexCoords | drm::kAttrCornerTexCoords);
    CornerValues inNormal{(wanted & drm::kAttrNormals) ? &input.normals : nullptr,
                          (wanted & drm::kAttrCornerNormals) ? &input.cornerNormals : nullptr, &input.triangles, 3};
    CornerValues outNormal{&out.normals, &out.cornerNormals, &out.triangles, 3};
    CornerValues inUv{(wanted & drm::kAttrTexCoords) ? &input.texCoords : nullptr,
                      (wanted & drm::kAttrCornerTexCoords) ? &input.cornerTexCoords : nullptr, &input.triangles, 2};
    CornerValues outUv{&out.texCoords, &out.cornerTexCoords, &out.triangles, 2};
    if (normals && !outNormal.present()) return "the decoded mesh has no normals";
    if (texCoords && !outUv.present()) return "the decoded mesh has no texture coordinates";
    const double bound = normalAngleBound(options.normalBits);
    const double uvTolerance =
        std::max(halfStep(input.cornerTexCoords, options.uvBits), halfStep(input.texCoords, options.uvBits));
    for (size_t i = 0; i < input.faceCount(); ++i)
        for (int k = 0; k < 3; ++k) {
            const size_t corner = inputCorner(encoded, i, k);
            const size_t decodedCorner = 3 * i + size_t(k);
            if (normals) {
                const float* a = inNormal.at(corner);
                const float* b = outNormal.at(decodedCorner);
                const bool zero = a[0] == 0 && a[1] == 0 && a[2] == 0;
                const double angle = angleDegrees(a, b);
                if (!zero && angle > bound)
                    return "the normal at " + cornerName(corner) + " turned by " + fixed(angle, 3) +
                           " degrees (the bound for " + std::to_string(options.normalBits) + " bits is " +
                           fixed(bound, 3) + ")";
            }
            if (texCoords) {
                const float* a = inUv.at(corner);
                const float* b = outUv.at(decodedCorner);
                for (int c = 0; c < 2; ++c) {
                    const double error = std::fabs(double(a[c]) - double(b[c]));
                    // Float rounding of the dequantized value on top of half a step.
                    const double slack = 4 * std::ldexp(std::fabs(double(a[c])) + uvTolerance, -24);
                    if (!(error <= uvTolerance + slack))
                        return "the texture coordinate at " + cornerName(corner) + " moved by " + std::to_string(error) +
                               " (half a step at " + std::to_string(options.uvBits) + " bits is " +
                               std::to_string(uvTolerance) + ")";
                }
            }
        }
    return "";
}

std::string findLosslessMismatch(const drm::Mesh& input, const drm::Encoded& encoded, const drm::Decoded& decoded) {
    if (encoded.stats.weldedVertices > 0) return findWeldedMismatch(input, encoded, decoded);
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
