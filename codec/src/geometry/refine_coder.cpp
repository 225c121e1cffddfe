#include "geometry/refine_coder.h"

#include <algorithm>
#include <array>
#include <string>

#include "common.h"
#include "container/byte_io.h"
#include "drmcodec/drmcodec.h"
#include "entropy/range_coder.h"
#include "entropy/rank_coder.h"

namespace drm {
namespace {

// Predictions carry kFraction bits below the grid step.
constexpr int kFraction = 2;
constexpr int64_t kScale = int64_t(1) << kFraction;

// Contexts: predictor kind x neighbour activity x earlier axes x clamped.
constexpr int kKinds = 3;        // parallelogram, neighbour average, none
constexpr int kActivities = 7;   // no refined neighbour, then 6 buckets of their mean residual
constexpr int kAxisClasses = 4;  // first axis; earlier axes' symbols summed 0, 1, 2+
constexpr int kContexts = kKinds * kActivities * kAxisClasses * 2;


int64_t floorDiv(int64_t a, int64_t b) {  // b > 0
    const int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

// The state both sides share: coarse positions of all vertices, full
// positions of the refined ones, the triangles around each vertex, and per
// predictor its residual sizes and adaptive models. The decoder follows
// the one predictor its file names; the encoder follows all of them at
// once: the refinement order and the refined positions are the same for
// every predictor, so the neighbours are gathered once a vertex (about
// two fifths of a pass), and only predictions, contexts and symbols are
// each predictor's own. Modes, the number of predictors followed, is fixed
// at compile time, so that the decoder's one-predictor loops unroll.
template <size_t Modes>
class Refiner {
public:
    Refiner(const std::vector<int32_t>& coarse, int lowBits, const std::vector<uint32_t>& triangles,
            const std::array<RefinePredictor, Modes>& predictors)
        : coarse_(coarse),
          triangles_(triangles),
          lowBits_(lowBits),
          cell_(int64_t(1) << lowBits),
          n_(coarse.size() / 3),
          full_(coarse.size(), 0),
          refined_(n_, 0) {
        static_assert(Modes >= 1 && Modes <= size_t(kRefinePredictors), "a refiner follows 1 to 4 predictors");
        for (size_t i = 0; i < Modes; ++i) {
            const RefinePredictor predictor = predictors[i];
            Mode& m = modes_[i];
            m.predictor = predictor;
            m.activity.assign(n_, 0);
            m.models.assign(size_t(kContexts), AdaptiveFrequencies(std::vector<uint16_t>(size_t(1) << lowBits, 1)));
            curvature_ |= predictor == RefinePredictor::Curvature;
        }
        // Triangles around each vertex (compressed rows), and the order of
        // refinement: vertices as the triangles first reach them, then the
        // vertices of no triangle in index order.
        const size_t faces = triangles.size() / 3;
        for (uint32_t v : triangles)
            if (v >= n_) throw Error(ErrorKind::Internal, "internal error: a refinement triangle names vertex " + std::to_string(v));
        first_.assign(n_ + 1, 0);
        for (uint32_t v : triangles) ++first_[v + 1];
        for (size_t v = 0; v < n_; ++v) first_[v + 1] += first_[v];
        incident_.resize(triangles.size());
        std::vector<uint32_t> fill(first_.begin(), first_.end() - 1);
        for (size_t f = 0; f < faces; ++f)
            for (int c = 0; c < 3; ++c) incident_[fill[triangles[3 * f + c]]++] = uint32_t(f);
        std::vector<uint8_t> queued(n_, 0);
        order_.reserve(n_);
        for (uint32_t v : triangles)
            if (!queued[v]) {
                queued[v] = 1;
                order_.push_back(v);
            }
        for (size_t v = 0; v < n_; ++v)
            if (!queued[v]) order_.push_back(uint32_t(v));
    }

    const std::vector<uint32_t>& order() const { return order_; }
    // A predictor the encoder gives up on is not followed further.
    void drop(int mode) { modes_[size_t(mode)].live = false; }
    bool live(int mode) const { return modes_[size_t(mode)].live; }

    // Prepares every live predictor's prediction for vertex v.
    void forecast(uint32_t v) {
        int64_t parallelogram[3] = {0, 0, 0}, average[3] = {0, 0, 0};
        int64_t parallelograms = 0, neighbours = 0, activityCount = 0;
        // Each predictor's residual sizes summed over the refined neighbours
        // (a dropped predictor's too, never read).
        constexpr size_t modeCount = Modes;
        const uint32_t* activityOf[Modes];
        int64_t activitySum[Modes] = {};
        for (size_t m = 0; m < modeCount; ++m) activityOf[m] = modes_[m].activity.data();
        for (uint32_t i = first_[v]; i < first_[v + 1]; ++i) {
            const uint32_t f = incident_[i];
            const uint32_t* t = &triangles_[3 * size_t(f)];
            const int at = t[0] == v ? 0 : t[1] == v ? 1 : 2;
            const uint32_t a = t[(at + 1) % 3], b = t[(at + 2) % 3];
            for (uint32_t u : {a, b}) {
                // Twice the position: full if refined, else the cell centre.
                for (int k = 0; k < 3; ++k) average[k] += twicePosition(u, k);
                ++neighbours;
                if (refined_[u]) {
                    for (size_t m = 0; m < modeCount; ++m) activitySum[m] += activityOf[m][u];
                    ++activityCount;
                }
            }
            if (!refined_[a] || !refined_[b] || a == b) continue;
            // The triangles across edge (a, b) with a refined third vertex.
            for (uint32_t j = first_[a]; j < first_[a + 1]; ++j) {
                const uint32_t g = incident_[j];
                if (g == f) continue;
                const uint32_t* s = &triangles_[3 * size_t(g)];
                if (s[0] != b && s[1] != b && s[2] != b) continue;
                const uint32_t c = s[0] != a && s[0] != b ? s[0] : s[1] != a && s[1] != b ? s[1] : s[2];
                if (c == a || c == b || c == v || !refined_[c]) continue;
                for (int k = 0; k < 3; ++k)
                    parallelogram[k] += int64_t(full_[3 * size_t(a) + k]) + full_[3 * size_t(b) + k] -
                                        full_[3 * size_t(c) + k];
                ++parallelograms;
            }
        }
        int64_t laplacian[3] = {0, 0, 0};  // in kScale units, summed over refined neighbours
        int64_t laplacians = 0;
        if (curvature_ && neighbours > 0) {
            for (uint32_t i = first_[v]; i < first_[v + 1]; ++i) {
                const uint32_t* t = &triangles_[3 * size_t(incident_[i])];
                for (int c = 0; c < 3; ++c) {
                    const uint32_t u = t[c];
                    if (u == v || !refined_[u]) continue;
                    int64_t sum[3] = {0, 0, 0}, count = 0;
                    for (uint32_t j = first_[u]; j < first_[u + 1]; ++j) {
                        const uint32_t* r = &triangles_[3 * size_t(incident_[j])];
                        for (int d = 0; d < 3; ++d) {
                            const uint32_t w = r[d];
                            if (w == u) continue;
                            for (int k = 0; k < 3; ++k) sum[k] += twicePosition(w, k);
                            ++count;
                        }
                    }
                    if (count == 0) continue;
                    for (int k = 0; k < 3; ++k)
                        laplacian[k] += floorDiv((2 * int64_t(full_[3 * size_t(u) + k]) * count - sum[k]) * kScale, 2 * count);
                    ++laplacians;
                }
            }
        }
        for (size_t mode = 0; mode < modeCount; ++mode) {
            Mode& m = modes_[mode];
            if (!m.live) continue;
            m.kind = parallelograms > 0 ? 0 : neighbours > 0 ? 1 : 2;
            if (m.predictor == RefinePredictor::Average && neighbours > 0) m.kind = 1;
            if (m.predictor == RefinePredictor::Curvature && neighbours > 0) m.kind = laplacians > 0 ? 0 : 1;
            m.activityClass = 0;
            if (activityCount > 0) {
                const int64_t twiceMean = (2 * activitySum[mode] + activityCount / 2) / activityCount;
                m.activityClass = 1 + std::min(bitLength(uint64_t(twiceMean)), kActivities - 2);
            }
            for (int k = 0; k < 3; ++k) {
                const int64_t low = (int64_t(coarse_[3 * size_t(v) + k]) << lowBits_) * kScale;
                int64_t p = 0;
                if (m.predictor == RefinePredictor::Curvature && m.kind == 0)
                    p = floorDiv(average[k] * kScale, 2 * neighbours) + floorDiv(laplacian[k], laplacians);
                else if (m.kind == 0 && m.predictor == RefinePredictor::Blend)
                    p = floorDiv(parallelogram[k] * kScale * neighbours + average[k] * kScale * parallelograms / 2,
                                 2 * parallelograms * neighbours);
                else if (m.kind == 0) p = floorDiv(parallelogram[k] * kScale, parallelograms);
                else if (m.kind == 1) p = floorDiv(average[k] * kScale, 2 * neighbours);
                else p = low + (cell_ - 1) * kScale / 2;
                const int64_t offset = p - low, top = (cell_ - 1) * kScale;
                m.clamped[k] = offset < 0 || offset > top;
                m.offset[k] = std::min(std::max(offset, int64_t(0)), top);
            }
            m.symbolSum = 0;
        }
    }

    AdaptiveFrequencies& model(int mode, int axis) {
        Mode& m = modes_[size_t(mode)];
        const int axisClass = axis == 0 ? 0 : 1 + std::min(m.symbolSum, 2);
        const int context = ((m.kind * kActivities + m.activityClass) * kAxisClasses + axisClass) * 2 + m.clamped[axis];
        return m.models[size_t(context)];
    }

    // Symbols order the cell's values by distance from the prediction,
    // nearer first, the lower value first on a tie.
    uint32_t symbolOf(int mode, int axis, uint32_t value) const {
        uint32_t symbol = 0;
        walk(mode, axis, [&](uint32_t candidate) { return candidate == value ? true : (++symbol, false); });
        return symbol;
    }
    uint32_t valueOf(int mode, int axis, uint32_t symbol) const {
        uint32_t value = 0;
        walk(mode, axis, [&](uint32_t candidate) {
            if (symbol == 0) {
                value = candidate;
                return true;
            }
            --symbol;
            return false;
        });
        return value;
    }

    void coded(int mode, uint32_t symbol) { modes_[size_t(mode)].symbolSum += int(symbol); }

    void settle(uint32_t v, const int32_t* position) {
        for (int k = 0; k < 3; ++k) full_[3 * size_t(v) + k] = position[k];
        for (Mode& m : modes_) {
            if (!m.live) continue;
            int64_t residual = 0;
            for (int k = 0; k < 3; ++k) {
                const int64_t p = m.offset[k] + (int64_t(coarse_[3 * size_t(v) + k]) << lowBits_) * kScale;
                const int64_t d = int64_t(position[k]) * kScale - p;
                residual += d < 0 ? -d : d;
            }
            m.activity[v] = uint32_t(std::min<int64_t>(residual / kScale, 0xFFFFFFF));
        }
        refined_[v] = 1;
    }

    int64_t twicePosition(uint32_t w, int k) const {
        return refined_[w] ? 2 * int64_t(full_[3 * size_t(w) + k])
                           : 2 * (int64_t(coarse_[3 * size_t(w) + k]) << lowBits_) + cell_ - 1;
    }

    int32_t cellLow(uint32_t v, int axis) const { return coarse_[3 * size_t(v) + axis] << lowBits_; }

private:
    template <typename Visit>
    void walk(int mode, int axis, Visit visit) const {
        const int64_t p = modes_[size_t(mode)].offset[axis];
        int64_t below = p / kScale, above = below + 1;  // below <= p < above (in steps)
        while (below >= 0 || above < cell_) {
            const bool takeBelow =
                below >= 0 && (above >= cell_ || p - below * kScale <= above * kScale - p);
            if (takeBelow) {
                if (visit(uint32_t(below))) return;
                --below;
            } else {
                if (visit(uint32_t(above))) return;
                ++above;
            }
        }
    }

    // One predictor's own state.
    struct Mode {
        RefinePredictor predictor = RefinePredictor::Parallelogram;
        bool live = true;
        std::vector<uint32_t> activity;  // per refined vertex: its residual's size under this predictor
        std::vector<AdaptiveFrequencies> models;
        int kind = 2, activityClass = 0, symbolSum = 0;
        int64_t offset[3] = {0, 0, 0};
        int clamped[3] = {0, 0, 0};
    };

    const std::vector<int32_t>& coarse_;
    const std::vector<uint32_t>& triangles_;
    int lowBits_;
    int64_t cell_;
    size_t n_;
    std::vector<int32_t> full_;
    std::vector<uint8_t> refined_;
    std::array<Mode, Modes> modes_;
    bool curvature_ = false;  // a Curvature predictor is followed: the Laplacians are gathered
    std::vector<uint32_t> first_, incident_, order_;
};

}  // namespace

std::vector<int32_t> coarsenGrid(const std::vector<int32_t>& grid, int lowBits) {
    std::vector<int32_t> coarse(grid.size());
    for (size_t i = 0; i < grid.size(); ++i) coarse[i] = grid[i] >> lowBits;
    return coarse;
}

std::vector<uint8_t> writeRefinePayload(int lowBits, const Refinement& refinement, const std::vector<uint8_t>& tree) {
    ByteWriter out;
    out.u8(uint8_t(lowBits));
    out.u8(uint8_t(refinement.predictor));
    out.varint(tree.size());
    out.bytes(tree);
    out.bytes(refinement.bytes);
    return std::move(out.buffer());
}

RefinePayload readRefinePayload(const uint8_t* data, size_t size, int bits) {
    ByteReader in(data, size, "geometry section");
    RefinePayload p;
    p.lowBits = in.u8("refinement bits");
    const int most = std::min(kMaxRefineBits, bits - 1);
    if (p.lowBits < 1 || p.lowBits > most)
        throw Error(ErrorKind::Corrupt, "corrupt file: " + std::to_string(p.lowBits) + " refinement bits at " + std::to_string(bits) +
                    "-bit quantization (allowed: 1 to " + std::to_string(most) + ")");
    const uint8_t predictor = in.u8("refinement predictor");
    if (predictor >= kRefinePredictors)
        throw Error(ErrorKind::Corrupt, "corrupt file: unknown refinement predictor " + std::to_string(predictor));
    p.predictor = RefinePredictor(predictor);
    p.treeSize = size_t(in.count("coarse tree size", in.remaining()));
    p.tree = in.bytes(p.treeSize, "coarse tree");
    p.refinementSize = in.remaining();
    p.refinement = in.bytes(p.refinementSize, "refinement");
    return p;
}

// Every predictor, followed together in one pass (Refiner), the smallest
// stream kept (the first of equal ones). A predictor is dropped as soon as
// its stream must take more than maxBytes. One pass for all shares the
// neighbours' gathering; the streams and the choice are those of coding
// each predictor alone.
Refinement encodeRefinement(const std::vector<int32_t>& fine, int lowBits, const std::vector<uint32_t>& triangles,
                            size_t maxBytes) {
    const std::vector<int32_t> coarse = coarsenGrid(fine, lowBits);
    std::array<RefinePredictor, kRefinePredictors> predictors;
    for (int p = 0; p < kRefinePredictors; ++p) predictors[size_t(p)] = RefinePredictor(p);
    Refiner<kRefinePredictors> refiner(coarse, lowBits, triangles, predictors);
    std::array<RangeEncoder, kRefinePredictors> coders;
    size_t liveCount = coders.size();
    for (uint32_t v : refiner.order()) {
        for (size_t m = 0; m < coders.size(); ++m)
            if (refiner.live(int(m)) && coders[m].bytesAtLeast() > maxBytes) {
                refiner.drop(int(m));
                --liveCount;
            }
        if (liveCount == 0) break;
        refiner.forecast(v);
        for (size_t m = 0; m < coders.size(); ++m) {
            if (!refiner.live(int(m))) continue;
            for (int k = 0; k < 3; ++k) {
                const uint32_t value = uint32_t(fine[3 * size_t(v) + k] - refiner.cellLow(v, k));
                const uint32_t symbol = refiner.symbolOf(int(m), k, value);
                refiner.model(int(m), k).encode(coders[m], symbol);
                refiner.coded(int(m), symbol);
            }
        }
        refiner.settle(v, &fine[3 * size_t(v)]);
    }
    Refinement best;
    best.overBudget = true;
    for (size_t m = 0; m < coders.size(); ++m) {
        if (!refiner.live(int(m))) continue;
        std::vector<uint8_t> bytes = coders[m].finish();
        if (bytes.size() > maxBytes || (!best.overBudget && bytes.size() >= best.bytes.size())) continue;
        best.predictor = predictors[m];
        best.bytes = std::move(bytes);
        best.overBudget = false;
    }
    if (best.overBudget) best.predictor = RefinePredictor::Parallelogram;
    return best;
}

std::vector<int32_t> decodeRefinement(const RefinePayload& payload, const std::vector<int32_t>& coarse,
                                      const std::vector<uint32_t>& triangles) {
    Refiner<1> refiner(coarse, payload.lowBits, triangles, {{payload.predictor}});
    RangeDecoder coder(payload.refinement, payload.refinementSize);
    std::vector<int32_t> fine(coarse.size());
    for (uint32_t v : refiner.order()) {
        refiner.forecast(v);
        int32_t* at = &fine[3 * size_t(v)];
        for (int k = 0; k < 3; ++k) {
            const uint32_t symbol = refiner.model(0, k).decode(coder);
            refiner.coded(0, symbol);
            at[k] = refiner.cellLow(v, k) + int32_t(refiner.valueOf(0, k, symbol));
        }
        refiner.settle(v, at);
        if (coder.bytesPastEnd() > 0)
            throw Error(ErrorKind::Corrupt, "corrupt file: the refinement section ends before vertex " + std::to_string(v));
    }
    return fine;
}

}  // namespace drm
