// One stream of distance ranks (paper, Table 1): the traversal walked over
// a numbered mesh's faces with their true apexes, each open edge's rank
// coded. A whole mesh is one stream; a mesh split for two decoding threads
// (connectivity_parts.h) is two.
#ifndef DRM_RANK_STREAM_H
#define DRM_RANK_STREAM_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "encode/encode_session.h"
#include "progress.h"

namespace drm {

// The faces one rank stream codes: a whole mesh's, or one of two
// connectivity parts (connectivity_parts.h). Both parts read the numbered
// mesh's faces and topology, passing over the other part's faces (copies
// of them would add about a quarter to the encoder's peak memory); part 2
// numbers its vertices from the split on.
struct RankStreamFaces {
    enum class Part { Whole, First, Second } part = Part::Whole;
    const std::vector<int32_t>* grid = nullptr;  // x, y, z of the stream's vertices
    uint32_t split = 0;                          // parts: where part 2's vertices begin
    size_t faceCount = 0;                        // the stream's
    const std::vector<uint32_t>* kept = nullptr;  // part 2: its vertices never culled
};
struct CodedRanks {
    bool complete = true;  // a part may leave faces no start reaches (below)
    std::vector<uint8_t> bytes;
    uint64_t components = 0;
    std::vector<uint32_t> faceOrder;  // numbered faces in decoded order (when the mesh was repaired)
    std::vector<uint32_t> triangles;  // as decoded, over the stream's vertices
};

// The smallest vertex of numbered face f: below the split, the face is part 1's.
inline uint32_t smallestVertex(const std::vector<uint32_t>& t, uint32_t f) {
    return std::min({t[3 * size_t(f)], t[3 * size_t(f) + 1], t[3 * size_t(f) + 2]});
}

// Walks the traversal over s's faces with their true apexes and codes each
// edge's rank (paper, Table 1). Ranks and the rank histogram go into result.
CodedRanks codeRanks(const RankStreamFaces& s, const EncodeSession& session, const NumberedMesh& numbered,
                     const Levers& levers, const ComponentStarts& starts, Encoded& result,
                     ProgressReporter& progress, double progressFrom, double progressSpan);

}  // namespace drm

#endif  // DRM_RANK_STREAM_H
