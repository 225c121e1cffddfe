// An attempt's vertex section (the geometry coder's output) and the
// ranked attempts built on it: the connectivity numbered the way the
// section orders the vertices, or coded early, before the section exists,
// in the order it will give.
#ifndef DRM_VERTEX_SECTION_H
#define DRM_VERTEX_SECTION_H

#include <cstdint>
#include <vector>

#include "encode/encode_session.h"
#include "geometry/geometry_coders.h"
#include "geometry/tree/tree_coder.h"
#include "progress.h"

namespace drm {

// The full grid's cheapest-first tree (choices as flags, the frame on, over
// the 4 nearest) as refine's estimates measure themselves against it: what
// each vertex cost when picked, and its section's size in bits.
struct TreeRival {
    std::vector<float> pickBits;
    double bits = 0;
};

// The vertex section of one attempt: the coder asked for, or its fallback
// where that is no larger. `rival`: set by codeVertexSection where refine's
// estimates will follow (the tree asked for by Auto, over
// kAutoRefineAboveBitsPerVertex, on a mesh of kEstimateBudgetFromVertices
// to kEstimateBudgetUpToVertices).
struct VertexSection {
    const GeometryCoderEntry* coder = nullptr;
    GeometryEncoding encoding;
    TreeRival rival;
};

// `asked` is Refine exactly when lowBits > 0 (encodeConnectivity).
// `trials` (may be null): what an earlier call worked out on the same grid
// (refineGeometryEstimate's trees).
VertexSection codeVertexSection(const std::vector<int32_t>& quantized, const EncodeOptions& options,
                                GeometryCoder asked, int lowBits, GeometryTreeTrials* trials, int threads);

// What an attempt's vertex section is, or where it comes from.
struct VertexSectionPlan {
    GeometryCoder coder = GeometryCoder::SpanningTree;  // coded with this coder (Refine exactly when lowBits > 0)
    int lowBits = 0;                                    // Refine: the low bits the refinement codes
    // What an earlier call worked out on the same grid (refineGeometryEstimate's trees), or null.
    GeometryTreeTrials* trials = nullptr;
    // The vertex section already coded for this attempt (codeVertexSection), taken; or null.
    VertexSection* coded = nullptr;
    // lowBits 0 only: the connectivity coded before the vertex section was
    // (encodeBeforeVertexSection); its attempt is taken where its numbering
    // is the section's, and freed either way. Or null.
    EarlyConnectivity* early = nullptr;
};

// Codes the vertex set as planned, numbers the cut mesh for the
// connectivity and encodes it.
Attempt encodeWithGeometry(const EncodeSession& session, const VertexSectionPlan& plan, ProgressReporter& progress);

// The first attempt's connectivity, coded before its vertex section
// (encodeConnectivity) in the numbering that section will most likely give:
// Morton order (docs/format.md, "Vertex numbering"), points on one grid
// point in input order. Where no two points coincide, that is certain;
// elsewhere connectivityOrder puts such points in input order too, and
// encodeWithGeometry compares the two numberings before it keeps the
// attempt.
// The file is written with an empty vertex section until encodeWithGeometry
// adds the section.
EarlyConnectivity encodeBeforeVertexSection(const EncodeSession& session, ProgressReporter& progress);

}  // namespace drm

#endif  // DRM_VERTEX_SECTION_H
