#include "encode/rank_stream.h"

#include <memory>
#include <string>

#include "connectivity/ranked/edge_model.h"
#include "connectivity/start_triangle.h"
#include "connectivity/traversal.h"
#include "entropy/rank_coder.h"
#include "spatial/morton.h"
#include "spatial/spatial_index.h"

namespace drm {

// Walks the traversal over s's faces with their true apexes and codes each
// edge's rank (paper, Table 1). Ranks and the rank histogram go into result.
CodedRanks codeRanks(const RankStreamFaces& s, const EncodeSession& session, const NumberedMesh& numbered,
                     const Levers& levers, const ComponentStarts& starts, Encoded& result,
                     ProgressReporter& progress, double progressFrom, double progressSpan) {
    using Part = RankStreamFaces::Part;
    const PreparedMesh& prepared = session.prepared;
    const EncodeOptions& options = session.options;
    CodedRanks out;
    const MeshTopology& topology = numbered.topology;
    const std::vector<uint32_t>& t = numbered.triangles;
    const std::vector<int32_t>& grid = *s.grid;
    const size_t faceCount = s.faceCount;
    const size_t traversalVertices = grid.size() / 3;
    const uint32_t offset = s.part == Part::Second ? s.split : 0;  // numbered index of the stream's vertex 0
    auto inStream = [&](uint32_t face) {
        return s.part == Part::Whole || (smallestVertex(t, face) < s.split) == (s.part == Part::First);
    };
    Stats& stats = result.stats;
    const std::unique_ptr<SpatialIndex> candidates = makeSpatialIndex(grid, options.index, IndexRole::Traversal);
    Traversal traversal(traversalVertices, faceCount, candidates.get());
    EdgeModel model(grid, options.bits - numbered.lowBits, numbered.predictor, options.curvature, levers,
                    faceCount, *candidates, traversal);
    if (s.part == Part::First) {
        model.setSeam(s.split);
        for (size_t v = s.split; v < traversalVertices; ++v) traversal.keepVertex(uint32_t(v));
    }
    if (s.part == Part::Second) {
        for (uint32_t v : *s.kept) traversal.keepVertex(v);
        model.setFirstPartBelowKey(mortonKeyOf(grid.data()));
    }
    RankEncoder coder(model.contextCount(), model.boundaryFlags());

    if (prepared.repaired) out.faceOrder.reserve(faceCount);
    size_t attachedCount = 0;
    StartCursor cursor(traversal);
    uint32_t lastStart = 0;
    auto codeComponentFrom = [&](uint32_t v, uint32_t givenFace) {
        // givenFace, or of the faces at v the one whose other two vertices
        // cost the fewest bits; rotated to begin at v, orientation kept.
        uint32_t f = 0, second = 0, third = 0;
        int fewestBits = 1 << 30;
        const uint32_t at = v + offset;
        for (uint32_t e = topology.start[at]; e < topology.start[at + 1]; ++e) {
            const uint32_t face = topology.out[e].face;
            if ((givenFace != kNoIndex && face != givenFace) || !inStream(face)) continue;
            const uint32_t b = topology.out[e].to - offset;
            // The face's third vertex: its three are distinct, so the xor
            // of all three, less v and b.
            const uint32_t c = (t[3 * size_t(face)] ^ t[3 * size_t(face) + 1] ^ t[3 * size_t(face) + 2] ^ at ^ (b + offset)) - offset;
            const int bits = bitLength(uint64_t(startGap(v, b, traversalVertices)) + 1) +
                             bitLength(uint64_t(startGap(v, c, traversalVertices)) + 1);
            if (bits < fewestBits) {
                fewestBits = bits;
                f = face;
                second = b;
                third = c;
            }
        }
        const uint32_t from = cursor.at(lastStart);
        coder.putStartGap(StartField::Skipped, uint32_t((uint64_t(v) + traversalVertices - from) % traversalVertices));
        coder.putStartGap(StartField::Second, startGap(v, second, traversalVertices));
        coder.putStartGap(StartField::Third, startGap(v, third, traversalVertices));
        lastStart = v;
        ++out.components;
        ++attachedCount;
        if (prepared.repaired) out.faceOrder.push_back(f);
        traversal.startComponent(v, second, third);
        OpenEdge edge;
        while (traversal.popOpenEdge(edge)) {
            uint32_t face = 0;
            uint32_t apex = topology.apexAcross(edge.vi + offset, edge.vj + offset, &face);
            if (apex != kNoVertex && !inStream(face)) apex = kNoVertex;  // the other part's: the seam
            if (apex != kNoVertex) apex -= offset;
            uint32_t rank = 0;
            // With boundary flags a boundary edge's rank 0 is the flag alone:
            // its candidates and context are not worked out (as decoding).
            const EdgeForecast& forecast = model.forecastBoundary(edge);
            if (apex != kNoVertex || !model.boundaryFlags()) model.forecastRank(edge);
            const int context = forecast.context, boundaryClass = forecast.boundaryClass;
            if (apex == kNoVertex) {
                traversal.closeAsBoundary(edge);
            } else {
                if (!model.admissible(apex, edge))
                    throw Error(ErrorKind::Internal, "internal error: the apex of face " + std::to_string(face) +
                                " is not a candidate; the file would not decode");
                rank = model.rankOf(apex, edge);
                model.resolved(apex);
                traversal.attachApex(edge, apex);
                if (prepared.repaired) out.faceOrder.push_back(face);
                result.faceRank[prepared.inputFace.empty() ? face : prepared.inputFace[face]] = rank;
                ++attachedCount;
            }
            coder.put(rank, context, boundaryClass);
            if (rank >= stats.rankHistogram.size()) stats.rankHistogram.resize(size_t(rank) + 1, 0);
            ++stats.rankHistogram[rank];
            progress.tick(progressFrom + progressSpan * double(attachedCount) / double(faceCount));
        }
    };
    auto startsAComponent = [&](uint32_t v) {
        if (traversal.isTouched(v)) return false;
        for (uint32_t e = topology.start[v + offset]; e < topology.start[v + offset + 1]; ++e)
            if (inStream(topology.out[e].face)) return true;
        return false;
    };
    if (starts.order == ComponentStarts::Order::InputFaces) {
        for (size_t f = 0; f < t.size() / 3; ++f)
            if (inStream(uint32_t(f)) && !traversal.isTouched(t[3 * f] - offset)) codeComponentFrom(t[3 * f] - offset, uint32_t(f));
    } else if (starts.firstVertex != kNoVertex && startsAComponent(starts.firstVertex)) {
        codeComponentFrom(starts.firstVertex, kNoIndex);
    }
    for (uint32_t v = 0; v < traversalVertices; ++v)
        if (startsAComponent(v)) codeComponentFrom(v, kNoIndex);

    if (attachedCount != faceCount) {
        // A part-2 component whose every vertex is kept and was reached
        // from other components (a triangle bordered by the seam on all
        // sides, touching the rest at its corners) has no untouched vertex
        // to start from: the caller codes the mesh in one part instead.
        // Part 1 cannot: each of its components has a vertex below the
        // split, whose faces are all part 1's, in one fan.
        if (s.part == Part::Second) {
            out.complete = false;
            return out;
        }
        throw Error(ErrorKind::Internal, "internal error: the traversal reached " + std::to_string(attachedCount) + " of " +
                    std::to_string(faceCount) + " faces");
    }
    out.bytes = coder.finish();
    out.triangles = traversal.takeTriangles();
    return out;
}

}  // namespace drm
