// The paper's choice of predictor for a mesh (Section 3.2).
#ifndef DRM_PREDICTOR_SELECTION_H
#define DRM_PREDICTOR_SELECTION_H

#include <vector>

#include "drmcodec/drmcodec.h"
#include "mesh/mesh_check.h"

namespace drm {

struct PredictorVotes {
    uint64_t parallelogram = 0;
    uint64_t midpoint = 0;
    Predictor winner() const { return parallelogram > midpoint ? Predictor::Parallelogram : Predictor::Midpoint; }
};

// For every face (over vertexCount vertices; on a mesh of over 131,072
// faces, for faces spread evenly, at most that many and at least half as
// many) not on the boundary at its chosen edge, with the face's third vertex opposite that edge and the
// apex of the face across as the target, gives a vote to each base
// predictor that lands closer to the apex than any of the apex's
// neighbours; when neither does, the nearer one gets the vote. Ties go to
// midpoint.
PredictorVotes countPredictorVotes(const std::vector<uint32_t>& triangles, size_t vertexCount, const MeshTopology& topology,
                                   const std::vector<int32_t>& grid);

}  // namespace drm

#endif  // DRM_PREDICTOR_SELECTION_H
