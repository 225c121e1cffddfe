#include "encode/refine_policy.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <future>
#include <optional>
#include <vector>

#include "concurrency.h"
#include "geometry/refine_coder.h"
#include "geometry/tree/spanning_tree.h"
#include "geometry/tree/tree_coder.h"

namespace drm {

namespace {

// Up to this many vertices, refine's attempts run beside the tree's, each
// after its estimate on that estimate's thread: the three attempts are
// held at once, so larger meshes make them one after the other, for memory
// (docs/tuning.md).
constexpr size_t kRefineAttemptsBesideUpToVertices = size_t(1) << 18;
// An attempt beside is made at once where its estimate would be worth it
// against a file this many times the tree's vertex section (the whole file
// is at most about 1.3 times the section on most meshes that try refine:
// docs/tuning.md); else it waits for the tree's attempt to tell its total.
constexpr double kSureTreeTotal = 1.2;

// GeometryCoder::Auto: the tree, and where it spends more than
// kAutoRefineAboveBitsPerVertex also refine with kAutoRefineLowBits (drmcodec.h);
// refine is kept where its file is at least kAutoRefineMinimumGainPercent
// smaller, since it decodes 20-30 % slower (a second pass over the
// triangles, ranks on a coarser grid). Refine never wins where the tree is
// cheap (scans sampled finer than the grid); where it wins, 4 low bits is
// nearly always best and 2 the rest, and trying 1..5 finds little more for
// three times the work (docs/tuning.md).
constexpr double kRefineMinimumGain = kAutoRefineMinimumGainPercent / 100.0;
// Meshes this small decode in well under a millisecond either way: refine
// is tried and kept wherever it is smaller.
constexpr size_t kRefineAnyGainBelowVertices = 1000;
// Below this many vertices, meshes decode in a few milliseconds either
// way: a refine attempt is made where its estimate, within its slack
// (kRefineEstimateSlack), promises a 1 % smaller file, and kept wherever it
// is smaller: asking 3 % here, as larger meshes do, would forgo refine on
// meshes such as mech-holes-shark, where it saves 2.4 %, and an estimate
// promising any gain at all would make attempts that lose (docs/tuning.md).
constexpr size_t kRefineSmallMeshBelowVertices = 8192;
constexpr double kRefineSmallMeshEstimatedGain = 0.01;

// Where the coarse grid leaves nearest neighbours at most this many coarse
// steps apart (the spacing the geometry tree measures), the connectivity
// ranked on it costs at least kCrowdedConnectivityGrowth bits per vertex
// more than on the full grid: neighbours crowd into ties (docs/tuning.md;
// GeometryRefine.ACrowdedCoarseGridCostsConnectivity checks it). A refine
// attempt whose vertex bits cannot pay for that growth as well is not made.
constexpr double kCrowdedCoarseSpacing = 3.0;
constexpr double kCrowdedConnectivityGrowth = 0.6;

// The estimate codes one coarse tree where the attempt keeps the smallest
// of several, so it may come out a little over the attempt's vertex bits
// (docs/tuning.md): an attempt is made where the estimate misses the gain
// asked by no more than this share of the tree's geometry.
constexpr double kRefineEstimateSlack = 0.015;

// Refine's vertex bits without the traversal: the low bits predicted
// across the input's triangles (the traversal rebuilds them in another
// order, which changes the refinement's size little), and the tree over the
// coarse grid. Decides whether a whole refine attempt is worth making; the
// tree it grows and codes is left in `trials` for that attempt. One tree
// only, the cheapest-first with its choices as flags: refine's own coarse
// tree takes the smallest of several (encodeRefineCoarse), which the
// estimate leaves to the attempt, so it may come out a little over the
// attempt's figure (kRefineEstimateSlack). It spares a second tree on the
// coarse grid wherever refine is not tried (venus, feline with 2 low bits).
// Past skipAbove the exact figure does not matter (the caller skips the
// attempt): SIZE_MAX is returned as soon as the estimate must exceed it.
//
// The refinement comes first, over the input's numbering (it visits the
// vertices as the triangles reach them, then those in no triangle in index
// order: in the coarse tree's numbering it takes the same bytes on every
// corpus mesh), so that the coarse tree knows the room left to it. With a
// rival (the full grid's tree, TreeRival), the coarse tree is then given up
// once it clearly cannot fit the room budgetAbove leaves (TreeBudget):
// without the budget, venus grows both coarse trees to the end for
// estimates that miss by 6 and 11 %. Where the tree is not given up the
// estimate is the same figure.
// budgetAbove is the same bound whatever the threads (the estimates
// beside the tree's attempt know no looser one), so that which trees are
// given up, and so the file, does not depend on them.
//
// How far the coarse tree's extrapolated section may run over its room
// before it is given up, as a share of the rival's section: from 4/16 of
// the vertices on, the extrapolation comes within 1.6 % of the end's
// figure on the corpus, and the trees given up run 4 % over or more
// (docs/tuning.md); feline's, whose estimates miss by less, are grown to
// the end.
constexpr double kEstimateGiveUpMargin = 0.03;
size_t refineGeometryEstimate(const std::vector<int32_t>& quantized, const std::vector<uint32_t>& triangles, int bits,
                              int lowBits, NeighbourIndex index, GeometryTreeTrials& trials, double skipAbove,
                              double budgetAbove, const TreeRival* rival) {
    if (skipAbove < 0) return SIZE_MAX;
    const Refinement refinement =
        encodeRefinement(quantized, lowBits, triangles, skipAbove < double(SIZE_MAX / 2) ? size_t(skipAbove) : SIZE_MAX);
    if (refinement.overBudget) return SIZE_MAX;
    const double room = skipAbove - double(refinement.bytes.size());
    TreeBudget budget;
    const bool budgeted = rival && !rival->pickBits.empty();
    if (budgeted) {
        budget.rivalPickBits = &rival->pickBits;
        budget.rivalBits = rival->bits;
        budget.bits = 8.0 * (budgetAbove - double(refinement.bytes.size()));
        budget.margin = kEstimateGiveUpMargin * rival->bits;
    }
    // The attempt grows its own trees on these trials, unbudgeted.
    const BudgetScope scope(trials, budgeted ? &budget : nullptr);
    const GeometryEncoding tree =
        encodeGeometryTree(coarsenGrid(quantized, lowBits), bits - lowBits, index, GeometryTree::CheapestFirst,
                           ChoiceCoding::Flags, FrameUse::On, &trials);
    if (tree.bytes.empty() || double(tree.bytes.size()) > room) return SIZE_MAX;
    return tree.bytes.size() + refinement.bytes.size();
}

}  // namespace

Attempt encodeWithChosenGeometry(const EncodeSession& session, VertexSection section, EarlyConnectivity* early,
                                 ProgressReporter& progress) {
    const Mesh& mesh = session.mesh;
    const PreparedMesh& prepared = session.prepared;
    const EncodeOptions& options = session.options;
    if (!section.coder)
        section = codeVertexSection(prepared.quantized, options, GeometryCoder::SpanningTree, 0, nullptr, threadsFor(options));
    const VertexSectionPlan tree{GeometryCoder::SpanningTree, 0, nullptr, &section, early};
    const size_t treeGeometry = section.encoding.bytes.size();
    const double treeBits = 8.0 * double(treeGeometry) / double(std::max<size_t>(1, mesh.vertexCount()));
    if (treeBits <= kAutoRefineAboveBitsPerVertex)
        return encodeWithGeometry(session, tree, progress);
    const double slack = kRefineEstimateSlack * double(treeGeometry);
    // The gain asked of an estimate before its attempt is made, and of an
    // attempt made before it is kept.
    const double minimumGain = mesh.vertexCount() < kRefineAnyGainBelowVertices      ? 0.0
                               : mesh.vertexCount() < kRefineSmallMeshBelowVertices ? kRefineSmallMeshEstimatedGain
                                                                                     : kRefineMinimumGain;
    const double keptGain = mesh.vertexCount() < kRefineSmallMeshBelowVertices ? 0.0 : minimumGain;
    // Refine's estimates (refineGeometryEstimate), one per low-bit count:
    // they need the tree's vertex section only, not its attempt, so they
    // may run beside it.
    struct Estimate {
        int lowBits = 0;
        GeometryTreeTrials trials;
        size_t bytes = SIZE_MAX;
        double growth = 0.0;              // the connectivity's growth on a crowded coarse grid, in bytes
        std::optional<Attempt> attempt;  // made beside the tree's attempt
        std::exception_ptr failure;      // what that attempt threw, reported only where it is kept
    };
    std::vector<Estimate> estimates;
    for (int lowBits : kAutoRefineLowBits)
        if (lowBits < options.bits) {
            estimates.emplace_back();
            estimates.back().lowBits = lowBits;
        }
    // The connectivity only grows on a coarser grid (more near ties), so
    // refine can win only where its vertex bits alone save the gain asked
    // of it: the estimate spares the whole attempt elsewhere (venus,
    // casting, anchor). It stops as soon as it must exceed skipAbove.
    // The rival the estimates' coarse trees measure themselves against
    // (held apart: the section itself goes to the tree's attempt).
    const TreeRival rival = std::move(section.rival);
    auto estimate = [&](Estimate& e, double treeTotal) {
        const double skipAbove = double(treeGeometry) + slack - minimumGain * treeTotal;
        const double budgetAbove = double(treeGeometry) + slack - minimumGain * double(treeGeometry);
        e.bytes = refineGeometryEstimate(prepared.quantized, mesh.triangles, options.bits, e.lowBits, options.index,
                                         e.trials, skipAbove, budgetAbove, &rival);
        e.growth = e.trials.nearest && e.trials.nearest->spacing <= kCrowdedCoarseSpacing
                       ? kCrowdedConnectivityGrowth * double(mesh.vertexCount()) / 8.0
                       : 0.0;
    };
    // Whether the estimate is worth an attempt against a file of treeTotal
    // bytes: every attempt made saves at least the gain asked, by the
    // estimate, within its slack.
    auto promising = [&](const Estimate& e, double treeTotal) {
        return e.bytes != SIZE_MAX && double(treeGeometry) + slack - double(e.bytes) - e.growth >= minimumGain * treeTotal;
    };
    const bool attemptsBeside = mesh.vertexCount() <= kRefineAttemptsBesideUpToVertices;
    // Set when this function leaves, the tree's attempt having thrown (a
    // cancel, an error) or every thread being done: an attempt beside
    // still running then stops at its next report (as Cancelled, which
    // nobody reads) instead of being waited for to its end.
    std::atomic<bool> leaving{false};
    std::vector<std::future<void>> estimating;  // declared after what the threads read: destroyed (and waited for) first
    // The tree attempt's total, for attempts that wait for it; declared
    // after the threads' futures, so that an exception breaks the promise
    // (waking them) before the futures wait for them.
    std::promise<size_t> treeTotalGiven;
    const std::shared_future<size_t> treeTotalKnown = treeTotalGiven.get_future().share();
    struct RaiseOnExit {
        std::atomic<bool>& flag;
        ~RaiseOnExit() { flag = true; }
    } raiseOnExit{leaving};  // declared last: raised first
    if (secondThreadAllowed(options)) {
        // Beside the attempt, whose total is not known yet, the estimates
        // stop at the looser bound a file no larger than its vertex section
        // gives: one stopped there would stop at the attempt's bound too,
        // and one not stopped gives the same figure, which the test below
        // holds to the attempt's bound. The files are the same. Each on a
        // thread of its own: together they take about twice the attempt's
        // time (venus), so on two cores the three end sooner than the
        // estimates one after the other beside it.
        // An estimate promising against that looser bound goes on to its
        // attempt on the same thread (each attempt is the same whenever it
        // is made): the test below keeps it only where the attempt's bound
        // would have made it. Attempts made one after the other once the
        // tree's is done would take a third longer on a mesh whose refine
        // attempts are large (armadillo-43k: docs/tuning.md).
        estimating.reserve(estimates.size());  // a push_back that threw would wait on a thread waiting here
        for (Estimate& each : estimates) {
            Estimate* e = &each;
            estimating.push_back(startBeside([&, e, treeGeometry, treeTotalKnown] {
                estimate(*e, double(treeGeometry));
                if (!attemptsBeside || !promising(*e, double(treeGeometry))) return;
                // Promising against any file up to kSureTreeTotal times the
                // tree's section: made at once. Less clearly: made once the
                // tree's attempt tells its total, and only where the test
                // below will keep it (camel's estimate with 2 low bits).
                if (!promising(*e, kSureTreeTotal * double(treeGeometry)) &&
                    !promising(*e, double(treeTotalKnown.get())))
                    return;
                const Progress untilLeaving = [&leaving](double, const char*) { return !leaving.load(); };
                ProgressReporter quiet(untilLeaving);  // shows nothing
                // An attempt made at once may be one the test below drops
                // (the tree's total past kSureTreeTotal times its section):
                // what it throws (out of memory) is kept for the test, and
                // reported only if the attempt is.
                try {
                    e->attempt = encodeWithGeometry(session, {GeometryCoder::Refine, e->lowBits, &e->trials}, quiet);
                } catch (...) {
                    e->failure = std::current_exception();
                }
                e->trials = GeometryTreeTrials();
            }));
        }
    }
    Attempt best = encodeWithGeometry(session, tree, progress);
    const size_t treeTotal = best.encoded.bytes.size();
    treeTotalGiven.set_value(treeTotal);
    // The attempts beside report nothing: waiting for them, this thread
    // reports, so that the bar moves and a cancel is seen (it raises
    // `leaving` on the way out, and they stop).
    for (std::future<void>& running : estimating) {
        while (running.wait_for(std::chrono::milliseconds(20)) == std::future_status::timeout)
            progress.stage("trying refine", 0.95);
        running.get();
    }
    if (estimating.empty())
        for (Estimate& e : estimates) estimate(e, double(treeTotal));
    const double worthIt = (1.0 - keptGain) * double(treeTotal);
    for (Estimate& e : estimates) {
        // The estimate's trees serve its own attempt only: freed after it
        // (the estimates ran together, so each one's are held till here).
        GeometryTreeTrials trials = std::move(e.trials);
        std::optional<Attempt> made = std::move(e.attempt);
        e.attempt.reset();
        if (!promising(e, double(treeTotal))) continue;
        if (e.failure) std::rethrow_exception(e.failure);
        Attempt refined =
            made ? std::move(*made) : encodeWithGeometry(session, {GeometryCoder::Refine, e.lowBits, &trials}, progress);
        if (double(refined.encoded.bytes.size()) <= worthIt && refined.encoded.bytes.size() < best.encoded.bytes.size())
            best = std::move(refined);
    }
    return best;
}

}  // namespace drm
