#include "encode/attempt_plan.h"

#include "encode/encode_session.h"
#include "encode/topological_attempt.h"
#include "geometry/geometry_coders.h"

namespace drm {

AttemptPlan planAttempts(const Mesh& mesh, const EncodeOptions& options, bool ranksOnly) {
    AttemptPlan plan;
    const bool ranksAskedFor = options.geometry != GeometryCoder::Auto || options.predictor != Predictor::Auto ||
                               options.curvature || options.connectivityParts != 0 ||
                               leversName(options.levers) != leversName(Levers());
    plan.coderChosen = !ranksOnly && options.connectivity == ConnectivityCoder::Auto && !ranksAskedFor;
    plan.hubs = plan.coderChosen && hasHubs(mesh);
    // The topological coder alone needs no vertex section of its own.
    plan.ranks = ranksOnly || (options.connectivity != ConnectivityCoder::Topological && !plan.hubs);
    const bool treeFirst = options.geometry == GeometryCoder::Auto || options.geometry == GeometryCoder::SpanningTree ||
                           (options.geometry == GeometryCoder::Refine && options.refineBits == 0);
    plan.firstCoder = treeFirst ? GeometryCoder::SpanningTree : options.geometry;
    plan.firstLowBits = options.geometry == GeometryCoder::Refine ? options.refineBits : 0;
    // The section's numbering is known before the section where it is on
    // the full grid, from a coder that does not keep the input's order.
    plan.earlyConnectivity = plan.ranks && secondThreadAllowed(options) && plan.firstLowBits == 0 &&
                             !geometryCoderOf(plan.firstCoder)->keepsInputOrder &&
                             mesh.vertexCount() <= kEarlyConnectivityUpToVertices;
    plan.firstSectionThreads =
        plan.earlyConnectivity && mesh.vertexCount() > kSectionThreadsBesideUpToVertices ? 1 : threadsFor(options);
    return plan;
}

}  // namespace drm
