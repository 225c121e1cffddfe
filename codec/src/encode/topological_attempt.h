// The topological connectivity coder's attempt (connectivity coder 2,
// topological_coder.h), and the test that sends a mesh to it alone: hubs,
// vertices of so many faces that the distance ranks would take quadratic
// time.
#ifndef DRM_TOPOLOGICAL_ATTEMPT_H
#define DRM_TOPOLOGICAL_ATTEMPT_H

#include <cstdint>
#include <optional>

#include "encode/encode_session.h"
#include "progress.h"

namespace drm {

// Whether a mesh has hubs enough for the ranks to take quadratic time
// (kHubWorkFloor). Indices in range (checkIndices).
bool hasHubs(const Mesh& mesh);

// The mesh by the topological coder (topological_coder.h): the
// connectivity named by topology, the positions in the order the walk
// meets them. The repairs and vertex order sections are as for ranks.
// giveUpAbove (0: never): the size of the file to beat; past it (by the
// coder's projection), or past the format's search bound, the attempt
// gives up and returns no file. `alone`: no ranks' attempt came before (for
// the progress bar).
constexpr uint64_t kNoRivalFile = ~uint64_t(0);  // a giveUpAbove for the search bound alone
std::optional<Attempt> encodeTopologically(const EncodeSession& session, bool alone, uint64_t giveUpAbove,
                                           ProgressReporter& progress);

}  // namespace drm

#endif  // DRM_TOPOLOGICAL_ATTEMPT_H
