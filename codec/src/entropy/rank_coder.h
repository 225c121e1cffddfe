// The connectivity stream coder: the paper's adaptive arithmetic coder with
// an order-1 context on ranks 1 and 2.
//
// Each rank is coded in a context made of the class of the previous rank
// (1, 2, or anything else) and a context index the caller supplies. Ranks
// below kRankDirectSymbols have a symbol each; larger ranks take an escape
// symbol followed by an Exp-Golomb code of rank - kRankDirectSymbols, so any
// uint32 can be coded.
//
// The stream also holds each component's start triangle, as three gaps
// (putStartGap) before the component's first rank.
//
// With the boundary flag lever every edge first gets a yes or no,
// "boundary edge", in a context of its class (EdgeModel's boundaryClass)
// and of whether the edge before was one; only an edge that is not gets a
// rank, and rank 0 then never comes.
#ifndef DRM_RANK_CODER_H
#define DRM_RANK_CODER_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "entropy/range_coder.h"

namespace drm {

// Ranks 0..kRankDirectSymbols-1 are coded as symbols of their own.
constexpr uint32_t kRankDirectSymbols = 24;
// The boundary flag's edge classes (the last three only in the two
// connectivity parts, for edges on the seam's side).
constexpr int kBoundaryClasses = 12;

// The fields of a start triangle (docs/format.md, "Start triangles"): the first
// vertex's distance from the decoder's cursor, then the other two vertices'
// distances past it. Each field has its own model of bit lengths.
enum class StartField { Skipped = 0, Second = 1, Third = 2 };
constexpr int kStartFields = 3;

// An adaptive frequency table over symbols 0..size-1: every coded symbol
// gains a fixed increment, and the counts are halved when their total grows
// past the range coder's limit, which also lets the table follow drift.
class AdaptiveFrequencies {
public:
    explicit AdaptiveFrequencies(const std::vector<uint16_t>& initialCounts);

    // Coder: a RangeEncoder or a CodingLog.
    template <class Coder>
    void encode(Coder& coder, uint32_t symbol) {
        uint32_t cum = 0;
        for (uint32_t s = 0; s < symbol; ++s) cum += counts_[s];
        coder.encode(cum, counts_[symbol], total_);
        update(symbol);
    }
    uint32_t decode(RangeDecoder& coder);
    // Counts symbol without coding it (for tables that only teach others).
    void observe(uint32_t symbol) { update(symbol); }
    // For an encoder estimating costs: count(s) / totalCount() is the
    // probability the table gives symbol s.
    uint32_t countOf(uint32_t s) const { return counts_[s]; }
    uint32_t totalCount() const { return total_; }
    // Restarts from parent's proportions, scaled to a total of about
    // `mass` (every count at least 1): a young context starts from what the
    // whole stream has shown so far instead of from a flat prior.
    void seedFrom(const AdaptiveFrequencies& parent, uint32_t mass);

private:
    void update(uint32_t symbol);

    std::vector<uint32_t> counts_;
    uint32_t total_ = 0;
};

// The rank tables: one per (previous rank class, caller context). A table
// is seeded when first used from a context-free table of its previous-rank
// class, which sees every symbol; so many contexts cost little on small
// meshes, whose contexts see few symbols each.
class RankContexts {
public:
    // boundaryFlags: rank 0 is coded apart (boundary flags), so the tables
    // start with the least count for it.
    RankContexts(int extraContexts, bool boundaryFlags);
    AdaptiveFrequencies& table(int previousClass, int extraContext);
    void observed(int previousClass, uint32_t symbol) { parents_[size_t(previousClass)].observe(symbol); }
    int extraContexts() const { return extraContexts_; }

private:
    int extraContexts_;
    std::vector<AdaptiveFrequencies> parents_;  // [previous rank class]
    std::vector<AdaptiveFrequencies> tables_;   // [previous rank class][extra context]
    std::vector<uint8_t> seeded_;
};

// The boundary flags: a yes/no table per edge class and whether
// the edge before was a boundary edge.
class BoundaryFlags {
public:
    explicit BoundaryFlags(bool on);
    bool on() const { return !tables_.empty(); }
    template <class Coder>
    void encode(Coder& coder, int edgeClass, bool boundary) {
        table(edgeClass).encode(coder, boundary ? 1 : 0);
        previous_ = boundary;
    }
    bool decode(RangeDecoder& coder, int edgeClass) {
        previous_ = table(edgeClass).decode(coder) != 0;
        return previous_;
    }

private:
    AdaptiveFrequencies& table(int edgeClass);
    std::vector<AdaptiveFrequencies> tables_;  // [edge class][previous edge a boundary]
    bool previous_ = false;
};

class RankEncoder {
public:
    // extraContexts >= 1 is the number of values of the caller's context.
    // boundaryFlags: a boundary flag before each rank.
    explicit RankEncoder(int extraContexts = 1, bool boundaryFlags = false);
    // rank: any value (0 = boundary edge); extraContext in [0, extraContexts);
    // boundaryClass in [0, kBoundaryClasses) with boundary flags, else
    // ignored.
    void put(uint32_t rank, int extraContext = 0, int boundaryClass = 0);
    // Any uint32 gap, as an adaptive Exp-Golomb code (its bit length in
    // field's model, then the bits below its leading one). The rank context
    // is left as it was.
    void putStartGap(StartField field, uint32_t gap);
    // Flushes and hands over the bytes; the encoder is spent.
    std::vector<uint8_t> finish();

private:
    RangeEncoder coder_;
    RankContexts ranks_;
    AdaptiveFrequencies escapeLengths_;       // bit lengths of escaped ranks
    std::vector<AdaptiveFrequencies> startLengths_;  // [StartField]: bit lengths of gap + 1
    BoundaryFlags boundary_;
    int previousClass_ = 0;
};

class RankDecoder {
public:
    RankDecoder(const uint8_t* data, size_t size, int extraContexts = 1, bool boundaryFlags = false);
    // The next rank. Throws Error if the stream holds a rank that does not
    // fit in 32 bits, or with boundary flags a rank 0 after a flag that said
    // no (corrupt data); otherwise any input decodes to values.
    // boundaryClass as RankEncoder::put takes it.
    uint32_t get(int extraContext = 0, int boundaryClass = 0);
    // get in two steps, for a caller that works out the rank's context
    // only for an edge that has an apex: with boundary flags, whether the
    // next edge is a boundary (its rank 0 then read whole; without the
    // flags, false, reading nothing); then, if it is not, its rank.
    bool getBoundaryFlag(int boundaryClass);
    uint32_t getRank(int extraContext);
    // The gap putStartGap coded; throws Error if it does not fit in 32 bits.
    uint32_t getStartGap(StartField field);
    // See RangeDecoder::bytesPastEnd: 0 after the last rank of an intact
    // stream.
    size_t bytesPastEnd() const { return coder_.bytesPastEnd(); }

private:
    RangeDecoder coder_;
    RankContexts ranks_;
    AdaptiveFrequencies escapeLengths_;
    std::vector<AdaptiveFrequencies> startLengths_;
    BoundaryFlags boundary_;
    int previousClass_ = 0;
};

}  // namespace drm

#endif  // DRM_RANK_CODER_H
