// The encoder's core (encoder.cpp): positions, connectivity and repairs,
// written as a file without attributes, and what the attribute coders
// need from it. encode() (mesh_codec.cpp) adds the attribute sections.
#ifndef DRM_ENCODER_H
#define DRM_ENCODER_H

#include <cstdint>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "container/file_format.h"
#include "progress.h"

namespace drm {

struct Attempt {
    Encoded encoded;  // the file without attribute sections, and its stats
    FileHeader header;
    std::vector<uint8_t> connectivity, geometry, vertexOrder, repairs;
    // The faces exactly as decode() gives them back (before attributes),
    // over decoded vertex indices.
    std::vector<uint32_t> decodedTriangles;
};

// Throws Error on meshes or options it cannot take. grid, if given, is the
// grid to use (a welded mesh keeps the grid of the mesh it was welded from).
Attempt encodeConnectivity(const Mesh& mesh, const EncodeOptions& options, ProgressReporter& progress,
                           const Grid* grid = nullptr);

}  // namespace drm

#endif  // DRM_ENCODER_H
