// An attempt by the distance ranks over one numbering of the mesh: the
// connectivity coded from every component start tried (and without levers
// where that is tried), the file written, the smallest kept.
#ifndef DRM_RANKED_ATTEMPT_H
#define DRM_RANKED_ATTEMPT_H

#include <cstdint>
#include <vector>

#include "encode/encode_session.h"
#include "progress.h"

namespace drm {

// Writes the attempt's file with the given vertex section. An attempt
// whose section is not coded yet (encodeBeforeVertexSection; lowBits 0, so
// no second pass) is written with an empty one, then again once it is:
// attempts over the same vertex section differ only in their other parts,
// so the smaller of two files is the same either way.
void writeAttempt(Attempt& attempt, GeometryCoder coder, std::vector<uint8_t> geometry);

// The repairs as the section stores them and undoCut replays them: an
// attempt's copies and faces repeating a vertex (in its decoded indices),
// the cut's flips and repeated faces in decoded face order (faceOrder:
// decoded face -> face of prepared.triangles).
Repairs repairsInDecodedOrder(const PreparedMesh& prepared, std::vector<uint32_t> copyOf, std::vector<uint32_t> looseTriangles,
                              const std::vector<uint32_t>& faceOrder);

// Numbers the cut mesh in numbered.order (connectivity index -> input
// index; the caller sets it and the vertex section's fields), over the
// points of vertexGrid (input order), and encodes the connectivity from
// every start tried, and without levers where that is tried.
Attempt encodeNumbered(const EncodeSession& session, NumberedMesh& numbered, const std::vector<int32_t>& vertexGrid,
                       ProgressReporter& progress);

}  // namespace drm

#endif  // DRM_RANKED_ATTEMPT_H
