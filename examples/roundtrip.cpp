// Encodes an octahedron, inspects the file, decodes it and checks that the
// same oriented triangles come back over the same grid points; then shows
// the kind of error a damaged file gives. Prints one line per step; exits
// non-zero on any mismatch. Uses only <drmcodec/drmcodec.h>.
#include <drmcodec/drmcodec.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>

namespace {

// A face as its corners' grid points, rotated so the smallest comes first
// (decode keeps each face's orientation, not its first corner).
using Face = std::array<std::array<int32_t, 3>, 3>;

std::vector<Face> facesOf(const std::vector<uint32_t>& triangles, const std::vector<int32_t>& grid) {
    std::vector<Face> faces;
    for (size_t f = 0; f < triangles.size() / 3; ++f) {
        Face face;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = triangles[3 * f + k];
            face[k] = {grid[3 * v], grid[3 * v + 1], grid[3 * v + 2]};
        }
        std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
        faces.push_back(face);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

}  // namespace

int main() {
    drm::Mesh mesh;
    mesh.positions = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    mesh.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

    drm::EncodeOptions options;
    options.bits = drm::kDefaultQuantizationBits;
    const drm::Encoded encoded = drm::encode(mesh, options);
    std::printf("encoded: %zu bytes (drm %s, format version %d)\n", encoded.bytes.size(), drm::version(),
                drm::kFileFormatVersion);

    const drm::FileInfo info = drm::inspect(encoded.bytes);
    std::printf("inspect: version %d, %llu vertices, %llu faces, %d bits\n", info.formatVersion,
                (unsigned long long)info.stats.vertices, (unsigned long long)info.stats.faces, info.stats.bits);
    if (info.stats.vertices != 6 || info.stats.faces != 8) return 1;

    const drm::Decoded decoded = drm::decode(encoded.bytes);
    // Lossless on the grid: the same oriented faces over the same grid points.
    if (facesOf(decoded.mesh.triangles, decoded.quantized) != facesOf(mesh.triangles, encoded.quantized)) {
        std::printf("decode: the faces differ\n");
        return 1;
    }
    std::printf("decode: %zu vertices, %zu faces, identical\n", decoded.mesh.vertexCount(), decoded.mesh.faceCount());

    std::vector<uint8_t> damaged = encoded.bytes;
    damaged[damaged.size() / 2] ^= 0x40;
    try {
        drm::decode(damaged);
        std::printf("damaged: decoded without complaint\n");
        return 1;
    } catch (const drm::Error& e) {
        std::printf("damaged: %s error: %s\n", drm::errorKindName(e.kind()), e.what());
        if (e.kind() != drm::ErrorKind::Corrupt) return 1;
    }
    return 0;
}
