#include "encode/verify.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace drm {
namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Angle between a decoded normal and an input normal (zero stays zero),
// from atan2 of the cross and dot products: exact near zero, where acos of
// a float dot product is not.
bool normalClose(const float* decoded, const float* input, double bound) {
    const double x = input[0], y = input[1], z = input[2];
    if (x == 0 && y == 0 && z == 0) return decoded[0] == 0 && decoded[1] == 0 && decoded[2] == 0;
    const double a = decoded[0], b = decoded[1], c = decoded[2];
    const double cx = b * z - c * y, cy = c * x - a * z, cz = a * y - b * x;
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), a * x + b * y + c * z) <= bound;
}

// Half a grid step of the texture coordinates (of either array), measured
// from the input's own range as the encoder quantizes it.
double halfUvStep(const std::vector<float>& uv, int bits) {
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    for (size_t i = 0; i < uv.size(); ++i) {
        const int k = int(i % 2);
        if (i < 2 || uv[i] < lo[k]) lo[k] = uv[i];
        if (i < 2 || uv[i] > hi[k]) hi[k] = uv[i];
    }
    const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    const double step = extent > 0 ? extent / double((uint32_t(1) << bits) - 1) : 1.0;
    return 0.5 * step * (1 + 1e-6) + 1e-7 * std::max({std::fabs(lo[0]), std::fabs(lo[1]), std::fabs(hi[0]), std::fabs(hi[1])});
}

}  // namespace

std::string findMismatch(const Mesh& in, const EncodeOptions& options, const Encoded& encoded) {
    Decoded d;
    try {
        d = decode(encoded.bytes);
    } catch (const Error& e) {
        return std::string("the decoder refuses it: ") + e.what();
    }
    const Mesh& out = d.mesh;
    const uint32_t keep = attributesOf(in) & options.attributes;
    const bool welded = encoded.stats.weldedVertices > 0 || out.vertexCount() != in.vertexCount();
    if (out.faceCount() != in.faceCount()) return "it has " + std::to_string(out.faceCount()) + " faces, not " + std::to_string(in.faceCount());
    if (out.vertexCount() != encoded.vertexOrder.size()) return "its vertex count differs from the encoder's vertex order";
    for (size_t v = 0; v < out.vertexCount(); ++v)
        for (int k = 0; k < 3; ++k)
            if (d.quantized[3 * v + k] != encoded.quantized[3 * size_t(encoded.vertexOrder[v]) + k])
                return "decoded vertex " + std::to_string(v) + " is not on its input vertex's grid point";
    auto sized = [&](uint32_t bit, size_t have, size_t want) { return !(keep & bit) || have == want; };
    const size_t V = out.vertexCount(), F = out.faceCount();
    if (!sized(kAttrColors, out.colors.size(), 4 * V) || !sized(kAttrNormals, out.normals.size(), 3 * V) ||
        !sized(kAttrTexCoords, out.texCoords.size(), 2 * V) || !sized(kAttrQuality, out.quality.size(), V) ||
        !sized(kAttrCornerTexCoords, out.cornerTexCoords.size(), 6 * F) ||
        !sized(kAttrCornerNormals, out.cornerNormals.size(), 9 * F) || !sized(kAttrFaceColors, out.faceColors.size(), 4 * F) ||
        !sized(kAttrFaceQuality, out.faceQuality.size(), F) ||
        !sized(kAttrFaceMaterial, out.faceMaterial.size(), in.faceMaterial.empty() ? 0 : F) ||
        !sized(kAttrFaceTexture, out.faceTexture.size(), in.faceTexture.empty() ? 0 : F))
        return "an attribute the input carries is missing or incomplete";
    const double normalBound = maxNormalError(options.normalBits);
    const double uvHalf = (keep & kAttrTexCoords) ? halfUvStep(in.texCoords, options.uvBits) : 0;
    const double cornerUvHalf = (keep & kAttrCornerTexCoords) ? halfUvStep(in.cornerTexCoords, options.uvBits) : 0;
    for (size_t f = 0; f < out.faceCount(); ++f) {
        const size_t g = encoded.faceOrder[f];
        const std::string face = "decoded face " + std::to_string(f) + " (input face " + std::to_string(g) + ")";
        for (size_t k = 0; k < 3; ++k) {
            const size_t ic = 3 * g + (k + encoded.faceRotation[f]) % 3, oc = 3 * f + k;
            const uint32_t u = in.triangles[ic], v = out.triangles[oc];
            if (welded) {
                for (int a = 0; a < 3; ++a)
                    if (d.quantized[3 * size_t(v) + a] != encoded.quantized[3 * size_t(u) + a])
                        return face + " has a corner on another grid point";
            } else if (encoded.vertexOrder[v] != u) {
                return face + " has other vertices than the input's";
            }
            if ((keep & kAttrColors) && std::memcmp(&out.colors[4 * v], &in.colors[4 * u], 4) != 0)
                return face + ": a vertex colour differs";
            if ((keep & kAttrNormals) && !normalClose(&out.normals[3 * v], &in.normals[3 * u], normalBound))
                return face + ": a vertex normal is off by more than the normal bits allow";
            if (keep & kAttrTexCoords)
                for (int a = 0; a < 2; ++a)
                    if (std::fabs(double(out.texCoords[2 * v + a]) - in.texCoords[2 * u + a]) > uvHalf)
                        return face + ": a texture coordinate is off by more than half a step";
            if ((keep & kAttrQuality) && !sameBits(out.quality[v], in.quality[u])) return face + ": a vertex quality differs";
            if (keep & kAttrCornerTexCoords)
                for (int a = 0; a < 2; ++a)
                    if (std::fabs(double(out.cornerTexCoords[2 * oc + a]) - in.cornerTexCoords[2 * ic + a]) > cornerUvHalf)
                        return face + ": a corner texture coordinate is off by more than half a step";
            if ((keep & kAttrCornerNormals) && !normalClose(&out.cornerNormals[3 * oc], &in.cornerNormals[3 * ic], normalBound))
                return face + ": a corner normal is off by more than the normal bits allow";
        }
        if ((keep & kAttrFaceColors) && std::memcmp(&out.faceColors[4 * f], &in.faceColors[4 * g], 4) != 0)
            return face + ": the face colour differs";
        if ((keep & kAttrFaceQuality) && !sameBits(out.faceQuality[f], in.faceQuality[g])) return face + ": the face quality differs";
        if ((keep & kAttrFaceMaterial) && !in.faceMaterial.empty() && out.faceMaterial[f] != in.faceMaterial[g])
            return face + ": the material differs";
        if ((keep & kAttrFaceTexture) && !in.faceTexture.empty() && out.faceTexture[f] != in.faceTexture[g])
            return face + ": the texture index differs";
    }
    if ((keep & kAttrFaceMaterial) && out.materials != in.materials) return "the material names differ";
    if ((keep & kAttrFaceTexture) && out.textures != in.textures) return "the texture names differ";
    if ((keep & kAttrMetadata) && out.metadata != in.metadata) return "the metadata differs";
    return "";
}

}  // namespace drm
