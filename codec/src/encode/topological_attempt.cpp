#include "encode/topological_attempt.h"

#include <vector>

#include "connectivity/topological/topological_coder.h"
#include "encode/ranked_attempt.h"
#include "mesh/vertex_order.h"
#include "stats.h"

namespace drm {

namespace {

// Hubs: the distance ranks' searches around a vertex of d faces cost about
// d^2 in all (its neighbours lie about it at like distances), where the
// topological coder's cost stays linear (docs/tuning.md). Where the faces
// at each vertex, squared and summed, pass this floor and this much a face,
// Auto codes topologically alone (the ranks only if that cannot be coded).
// Ordinary meshes sum about 18 a face (valence 6); the corpus's most, crank
// (a vertex of 132 faces), stays far below.
constexpr uint64_t kHubWorkFloor = uint64_t(1) << 22;
constexpr uint64_t kHubWorkPerFace = 64;

}  // namespace

bool hasHubs(const Mesh& mesh) {
    std::vector<uint32_t> facesAt(mesh.vertexCount(), 0);
    for (uint32_t v : mesh.triangles) ++facesAt[v];
    uint64_t work = 0;
    for (uint32_t d : facesAt) work += uint64_t(d) * d;
    return work > kHubWorkFloor + kHubWorkPerFace * uint64_t(mesh.faceCount());
}

std::optional<Attempt> encodeTopologically(const EncodeSession& session, bool alone, uint64_t giveUpAbove,
                                           ProgressReporter& progress) {
    const Mesh& mesh = session.mesh;
    const PreparedMesh& prepared = session.prepared;
    const ManifoldCut& cut = session.cut;
    const EncodeOptions& options = session.options;
    progress.stage("coding topologically", alone ? 0.01 : 0.9);
    const size_t originals = mesh.vertexCount(), copies = cut.copyOf.size();
    std::vector<int32_t> grid(prepared.quantized);  // copies at their originals' grid points
    grid.reserve(3 * (originals + copies));
    for (uint32_t original : cut.copyOf)
        for (int k = 0; k < 3; ++k) grid.push_back(prepared.quantized[3 * size_t(original) + size_t(k)]);
    TopologicalLayout layout;
    TopologicalBudget budget;
    // The faces as given passed the check, and a cut's are codable by
    // construction (the walk would throw on any that is not).
    budget.meshChecked = true;
    budget.giveUpAbove = giveUpAbove;
    // Alone it is the whole encoding (to 0.95); after the ranks, their
    // last stretch.
    budget.progress = alone ? WalkProgress{&progress, 0.01, 0.94} : WalkProgress{&progress, 0.9, 0.05};
    TopologicalStreams streams = encodeTopological(grid, prepared.grid.bits, *prepared.triangles, cut.copyOf, &layout, nullptr, budget);
    if (!streams.complete) return std::nullopt;
    // Decoded vertex -> input vertex: of an input vertex and its copies, the
    // one the walk met first is decoded as the original.
    std::vector<uint32_t> order(originals);
    std::vector<uint32_t> decodedIndex(originals);  // input vertex -> decoded
    for (size_t d = 0; d < originals; ++d) {
        const uint32_t v = layout.vertexOf[d];
        order[d] = v < originals ? v : cut.copyOf[v - originals];
        decodedIndex[order[d]] = uint32_t(d);
    }

    Attempt attempt;
    Encoded& result = attempt.encoded;
    result.grid = prepared.grid;
    const size_t faceCount = layout.faceOf.size();
    FileHeader header;
    header.vertexCount = originals;
    header.faceCount = faceCount + cut.looseTriangles.size() / 3 + prepared.repairs.duplicateOf.size();
    header.hasRepairs = prepared.repaired;
    header.copyCount = copies;
    header.grid = result.grid;
    header.connectivityCoder = ConnectivityCoder::Topological;
    // The fields the ranks would read: fixed, and meaningless here.
    header.predictor = Predictor::Parallelogram;
    header.levers = Levers::none();
    header.keepsVertexOrder = options.keepVertexOrder;
    header.componentCount = layout.components;

    Repairs inDecodedOrder;
    if (prepared.repaired) {
        std::vector<uint32_t> loose(cut.looseTriangles.size());
        for (size_t c = 0; c < loose.size(); ++c) loose[c] = decodedIndex[cut.looseTriangles[c]];
        inDecodedOrder = repairsInDecodedOrder(prepared, layout.copyOf, std::move(loose), layout.faceOf);
        attempt.repairs = encodeRepairs(inDecodedOrder, originals);
    }
    if (options.keepVertexOrder) attempt.vertexOrder = encodeVertexOrder(order);
    attempt.decodedTriangles = std::move(layout.triangles);
    if (prepared.repaired) undoCut(attempt.decodedTriangles, inDecodedOrder, originals);
    if (options.keepVertexOrder) {
        for (uint32_t& v : attempt.decodedTriangles) v = order[v];
        for (size_t v = 0; v < order.size(); ++v) order[v] = uint32_t(v);
    }
    result.vertexOrder = std::move(order);
    result.faceRank.assign(prepared.inputFaces, 0);  // no ranks
    attempt.header = header;
    attempt.connectivity = std::move(streams.connectivity);
    fillStatsFromTraversal(result.stats, 0, inDecodedOrder);
    result.stats.boundaryEdges = layout.boundaryEdges;
    writeAttempt(attempt, GeometryCoder::SpanningTree, std::move(streams.geometry));
    return attempt;
}

}  // namespace drm
