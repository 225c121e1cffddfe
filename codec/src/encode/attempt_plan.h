// The encoder's strategy: which attempts it makes at one mesh, and why.
// Every attempt writes a whole file; the smallest is kept (ties: the
// earlier attempt). In order:
//
// 1. The topological coder alone (connectivity coder 2), where asked for,
//    or where Auto chooses the coder and the mesh has hubs: the ranks'
//    searches around a vertex of d faces cost about d^2. If it cannot code
//    the mesh within the format's search bound, the ranks do (2 on).
// 2. The first ranked attempt: the vertex section by the coder asked for
//    (Auto and Refine with its low bits left to the encoder: the spanning
//    tree). With a second thread the section is coded there while this
//    thread checks and cuts the mesh, and, for a coder that orders the
//    vertices itself, codes the connectivity early in the numbering the
//    section will give (encodeBeforeVertexSection).
// 3. Within each ranked attempt (ranked_attempt.cpp, vertex_section.cpp):
//    small meshes also try other component starts, the section's own
//    numbering and, smallest of all, no levers.
// 4. GeometryCoder::Auto: refine with the low bits of
//    kAutoRefineLowBits where the tree spends over
//    kAutoRefineAboveBitsPerVertex and an estimate promises a smaller file
//    (refine_policy.h). Refine with no low bits given: every low-bit count
//    up to kMaxTriedRefineBits.
// 5. Where Auto chooses the connectivity coder: the topological coder
//    after the ranks, giving up once its projection passes the ranks' file
//    by kTopologicalGiveUp.
#ifndef DRM_ATTEMPT_PLAN_H
#define DRM_ATTEMPT_PLAN_H

#include "drmcodec/drmcodec.h"

namespace drm {

struct AttemptPlan {
    // ConnectivityCoder::Auto with nothing asked for that only the ranks
    // have (a vertex coder, a predictor, levers, curvature, parts): the
    // encoder chooses the connectivity coder (steps 1 and 5).
    bool coderChosen = false;
    // coderChosen, and the mesh has hubs (hasHubs): topological alone.
    bool hubs = false;
    // The distance ranks make the attempts (else step 1 alone).
    bool ranks = true;
    // The first ranked attempt's vertex section (step 2).
    GeometryCoder firstCoder = GeometryCoder::SpanningTree;
    int firstLowBits = 0;
    // Its connectivity coded early, beside its vertex section.
    bool earlyConnectivity = false;
    // The threads its vertex section may spread over: one where it runs
    // beside the early connectivity on a large mesh (kSectionThreadsBesideUpToVertices).
    int firstSectionThreads = 1;
};

// The plan for a mesh with these options (checked). ranksOnly: the plan
// after the topological coder gave up (step 1's fallback).
AttemptPlan planAttempts(const Mesh& mesh, const EncodeOptions& options, bool ranksOnly = false);

}  // namespace drm

#endif  // DRM_ATTEMPT_PLAN_H
