// A mesh and the rank code of each of its faces, from a mesh file (encoded
// with the command's options) or from a .drm file (its own ranks): what
// `drm ranks` and `drm render --by-rank` colour.
#ifndef DRM_TOOLS_RANKED_MESH_H
#define DRM_TOOLS_RANKED_MESH_H

#include "cli.h"

#include <drmcodec/drmcodec.h>

#include <cstdint>
#include <string>
#include <vector>

namespace drm {
namespace cli {

struct RankedMesh {
    drm::Mesh mesh;
    // faceRank[f]: the rank code that created face f, 0 for a start triangle.
    std::vector<uint32_t> faceRank;
    drm::Stats stats;                // of the .drm file, read or made
    std::vector<std::string> notes;  // the mesh reader's (see LoadedMesh)
};

// IN ending in .drm is decoded, and encode options in `parsed` are then a
// UsageError (the file's own are used); any other IN is loaded, checked and
// encoded with them. Throws drm::Error("cannot decode/encode IN: ...").
RankedMesh loadRankedMesh(const std::string& input, const Arguments& parsed, ProgressBar& bar);

// Decodes a .drm file: its mesh, ranks and stats. Throws drm::Error.
RankedMesh decodeRankedMesh(const std::string& input, ProgressBar& bar);

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_RANKED_MESH_H
