// Where a numbered mesh splits into the two connectivity parts that decode
// on two threads (connectivity_parts.h), and whether it is worth it.
#ifndef DRM_CONNECTIVITY_SPLIT_H
#define DRM_CONNECTIVITY_SPLIT_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "encode/encode_session.h"

namespace drm {

// Whether this attempt may split its connectivity in two parts
// (splitFaces has the last word).
bool maySplitConnectivity(const NumberedMesh& numbered, const EncodeOptions& options);

// The two parts of the numbered mesh's faces (connectivity_parts.h):
// where they split, part 2's vertices, and those of them never culled.
struct SplitFaces {
    uint32_t split = 0;
    size_t firstFaces = 0;
    std::vector<int32_t> secondGrid;
    std::vector<uint32_t> keptInSecond;
};
// False where the mesh stays whole: unless whateverItCosts, a long seam or
// parts too uneven to gain much from a second thread.
bool splitFaces(const NumberedMesh& numbered, bool whateverItCosts, SplitFaces& parts);

}  // namespace drm

#endif  // DRM_CONNECTIVITY_SPLIT_H
