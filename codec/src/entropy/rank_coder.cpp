#include "entropy/rank_coder.h"

#include <string>

#include "common.h"
#include "drmcodec/drmcodec.h"

namespace drm {

namespace {

// A coded symbol's count grows by kIncrement; once the total passes kLimit
// all counts are halved (rounding up, so none reaches zero), so a context
// weighs roughly its last 1000-2000 symbols: a balance between stationary
// and drifting statistics (docs/tuning.md).
constexpr uint32_t kIncrement = 32;
constexpr uint32_t kLimit = kRangeCoderMaxTotal;

constexpr uint32_t kEscape = kRankDirectSymbols;

// A seeded context starts with a total count of at most kSeedMass, worth 8
// observations (increment 32): enough to carry the parent's skew, little
// enough to yield to the context's own statistics.
constexpr uint32_t kSeedMass = 256;
// Escaped ranks code w = rank - kRankDirectSymbols + 1 >= 1 as its bit
// length (1..32, an adaptive symbol) followed by the bits below its leading
// one. A length of 32 is only valid for the few largest ranks; a decoded w
// that overflows uint32 ranks is rejected as corrupt.
constexpr uint32_t kMaxEscapeBits = 32;

// Starting counts of the rank symbols. Nearly all ranks are 1 and 2 with
// 0 and 3 next, so starting them ahead shortens the learning phase of each
// context; they weigh one or two observations, so real statistics soon
// override them (docs/tuning.md). Every symbol needs a count of at least 1.
// With boundary flags rank 0 never comes as a rank: it keeps
// the least count.
std::vector<uint16_t> rankPrior(bool boundaryFlags) {
    std::vector<uint16_t> counts(kRankDirectSymbols + 1, 1);
    counts[0] = boundaryFlags ? 1 : 4;
    counts[1] = 32;
    counts[2] = 8;
    counts[3] = 2;
    return counts;
}

std::vector<uint16_t> escapeLengthPrior() { return std::vector<uint16_t>(kMaxEscapeBits, 1); }

// A start gap g codes w = g + 1 (1 .. 2^32) as its bit length, 1..33.
constexpr uint32_t kMaxStartGapBits = 33;
std::vector<AdaptiveFrequencies> startLengthModels() {
    return std::vector<AdaptiveFrequencies>(kStartFields,
                                            AdaptiveFrequencies(std::vector<uint16_t>(kMaxStartGapBits, 1)));
}

// w >= 1 as its bit length (a symbol of `lengths`, coded as length - 1)
// and the bits below its leading one: escaped ranks and start gaps alike.
void encodeExpGolomb(RangeEncoder& coder, AdaptiveFrequencies& lengths, uint64_t w) {
    const int length = bitLength(w);
    lengths.encode(coder, uint32_t(length - 1));
    coder.encodeWideBits(w, length - 1);
}

uint64_t decodeExpGolomb(RangeDecoder& coder, AdaptiveFrequencies& lengths) {
    const int length = int(lengths.decode(coder)) + 1;
    return (uint64_t(1) << (length - 1)) | coder.decodeWideBits(length - 1);
}

int rankClass(uint32_t rank) { return rank == 1 ? 1 : rank == 2 ? 2 : 0; }
constexpr int kRankClasses = 3;

int checkedExtraContexts(int extraContexts) {
    if (extraContexts < 1)
        throw Error(ErrorKind::Internal, "internal error: the rank coder needs at least one context, not " +
                    std::to_string(extraContexts));
    return extraContexts;
}

void checkExtraContext(int extraContext, int extraContexts) {
    if (extraContext < 0 || extraContext >= extraContexts)
        throw Error(ErrorKind::Internal, "internal error: rank context " + std::to_string(extraContext) +
                    " is outside [0, " + std::to_string(extraContexts) + ")");
}


}  // namespace

AdaptiveFrequencies::AdaptiveFrequencies(const std::vector<uint16_t>& initialCounts)
    : counts_(initialCounts.begin(), initialCounts.end()) {
    for (uint32_t c : counts_) total_ += c;
}

uint32_t AdaptiveFrequencies::decode(RangeDecoder& coder) {
    const uint32_t target = coder.decodeFreq(total_);
    // Linear search: the common ranks are the first symbols, so this
    // usually stops after two steps. target < total_ bounds it.
    uint32_t symbol = 0;
    uint32_t cum = 0;
    while (cum + counts_[symbol] <= target) cum += counts_[symbol++];
    coder.consume(cum, counts_[symbol], total_);
    update(symbol);
    return symbol;
}

void AdaptiveFrequencies::seedFrom(const AdaptiveFrequencies& parent, uint32_t mass) {
    if (parent.total_ <= mass) {  // still (near) its prior: copy, never inflate
        counts_ = parent.counts_;
        total_ = parent.total_;
        return;
    }
    total_ = 0;
    for (size_t s = 0; s < counts_.size(); ++s) {
        const uint64_t scaled = uint64_t(parent.counts_[s]) * mass / parent.total_;
        counts_[s] = scaled > 0 ? uint32_t(scaled) : 1;
        total_ += counts_[s];
    }
}

void AdaptiveFrequencies::update(uint32_t symbol) {
    counts_[symbol] += kIncrement;
    total_ += kIncrement;
    if (total_ <= kLimit) return;
    total_ = 0;
    for (uint32_t& c : counts_) {
        c = (c + 1) >> 1;
        total_ += c;
    }
}

RankContexts::RankContexts(int extraContexts, bool boundaryFlags)
    : extraContexts_(checkedExtraContexts(extraContexts)),
      parents_(kRankClasses, AdaptiveFrequencies(rankPrior(boundaryFlags))),
      tables_(size_t(kRankClasses) * size_t(extraContexts_), AdaptiveFrequencies(rankPrior(boundaryFlags))),
      seeded_(tables_.size(), 0) {}

AdaptiveFrequencies& RankContexts::table(int previousClass, int extraContext) {
    checkExtraContext(extraContext, extraContexts_);
    const size_t index = size_t(previousClass * extraContexts_ + extraContext);
    if (!seeded_[index]) {
        tables_[index].seedFrom(parents_[size_t(previousClass)], kSeedMass);
        seeded_[index] = 1;
    }
    return tables_[index];
}

BoundaryFlags::BoundaryFlags(bool on) {
    // "Not a boundary edge" starts four times as likely: most edges are not
    // (a closed mesh has none), and borders soon teach their classes.
    if (on) tables_.assign(2 * kBoundaryClasses, AdaptiveFrequencies({4, 1}));
}

AdaptiveFrequencies& BoundaryFlags::table(int edgeClass) {
    if (edgeClass < 0 || edgeClass >= kBoundaryClasses)
        throw Error(ErrorKind::Internal, "internal error: boundary class " + std::to_string(edgeClass) + " is outside [0, " +
                    std::to_string(kBoundaryClasses) + ")");
    return tables_[size_t(2 * edgeClass + (previous_ ? 1 : 0))];
}

RankEncoder::RankEncoder(int extraContexts, bool boundaryFlags)
    : ranks_(extraContexts, boundaryFlags), escapeLengths_(escapeLengthPrior()), startLengths_(startLengthModels()),
      boundary_(boundaryFlags) {}

void RankEncoder::put(uint32_t rank, int extraContext, int boundaryClass) {
    if (boundary_.on()) {
        boundary_.encode(coder_, boundaryClass, rank == 0);
        if (rank == 0) {
            previousClass_ = rankClass(0);
            return;
        }
    }
    AdaptiveFrequencies& model = ranks_.table(previousClass_, extraContext);
    const uint32_t symbol = rank < kRankDirectSymbols ? rank : kEscape;
    model.encode(coder_, symbol);
    ranks_.observed(previousClass_, symbol);
    previousClass_ = rankClass(rank);
    if (rank < kRankDirectSymbols) return;
    encodeExpGolomb(coder_, escapeLengths_, uint64_t(rank) - kRankDirectSymbols + 1);
}

void RankEncoder::putStartGap(StartField field, uint32_t gap) {
    encodeExpGolomb(coder_, startLengths_[size_t(field)], uint64_t(gap) + 1);
}

std::vector<uint8_t> RankEncoder::finish() { return coder_.finish(); }

RankDecoder::RankDecoder(const uint8_t* data, size_t size, int extraContexts, bool boundaryFlags)
    : coder_(data, size), ranks_(extraContexts, boundaryFlags), escapeLengths_(escapeLengthPrior()),
      startLengths_(startLengthModels()), boundary_(boundaryFlags) {}

uint32_t RankDecoder::getStartGap(StartField field) {
    const uint64_t w = decodeExpGolomb(coder_, startLengths_[size_t(field)]);
    if (w - 1 > UINT32_MAX)
        throw Error(ErrorKind::Corrupt, "corrupt connectivity stream: a start triangle's gap does not fit in 32 bits");
    return uint32_t(w - 1);
}

uint32_t RankDecoder::get(int extraContext, int boundaryClass) {
    if (boundary_.on() && getBoundaryFlag(boundaryClass)) return 0;
    return getRank(extraContext);
}

bool RankDecoder::getBoundaryFlag(int boundaryClass) {
    if (!boundary_.on() || !boundary_.decode(coder_, boundaryClass)) return false;  // no flags: never a boundary flag
    previousClass_ = rankClass(0);
    return true;
}

uint32_t RankDecoder::getRank(int extraContext) {
    AdaptiveFrequencies& model = ranks_.table(previousClass_, extraContext);
    uint32_t rank = model.decode(coder_);
    if (rank == 0 && boundary_.on())
        throw Error(ErrorKind::Corrupt, "corrupt connectivity stream: rank 0 after a boundary flag that said no");
    ranks_.observed(previousClass_, rank);
    if (rank == kEscape) {
        const uint64_t w = decodeExpGolomb(coder_, escapeLengths_);
        const uint64_t wide = w - 1 + kRankDirectSymbols;
        if (wide > UINT32_MAX)
            throw Error(ErrorKind::Corrupt, "corrupt connectivity stream: an escaped rank does not fit in 32 bits");
        rank = uint32_t(wide);
    }
    previousClass_ = rankClass(rank);
    return rank;
}

}  // namespace drm
