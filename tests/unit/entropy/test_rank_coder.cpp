// The rank stream coder: exact round trips of any uint32 rank in any
// context, coded size against the empirical entropy of typical rank
// streams, and behaviour on truncated and garbage input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "entropy/rank_coder.h"

namespace {

struct Coded {
    uint32_t rank;
    int context;
};

std::vector<uint8_t> encodeAll(const std::vector<Coded>& ranks, int extraContexts) {
    drm::RankEncoder encoder(extraContexts);
    for (const Coded& c : ranks) encoder.put(c.rank, c.context);
    return encoder.finish();
}

void expectRoundTrip(const std::vector<Coded>& ranks, int extraContexts) {
    const std::vector<uint8_t> bytes = encodeAll(ranks, extraContexts);
    drm::RankDecoder decoder(bytes.data(), bytes.size(), extraContexts);
    for (size_t i = 0; i < ranks.size(); ++i)
        ASSERT_EQ(decoder.get(ranks[i].context), ranks[i].rank) << "rank " << i;
    EXPECT_EQ(decoder.bytesPastEnd(), 0u);
}

// Rank 1 almost always, then 2, 3 and 0 (a boundary edge), then a thin tail:
// the histogram the paper's predictors produce on typical meshes.
std::discrete_distribution<uint32_t> typicalRanks() {
    return std::discrete_distribution<uint32_t>(
        {0.003, 0.93, 0.06, 0.005, 0.001, 0.0005, 0.0002, 0.0001, 0.0001, 0.0001});
}

// Ideal code length in bits of symbols that are i.i.d. within each context,
// given their empirical counts: sum over contexts of n_c * H(empirical_c).
double empiricalEntropyBits(const std::map<int, std::map<uint32_t, uint64_t>>& counts) {
    double bits = 0;
    for (const auto& context : counts) {
        uint64_t n = 0;
        for (const auto& c : context.second) n += c.second;
        for (const auto& c : context.second)
            bits += double(c.second) * std::log2(double(n) / double(c.second));
    }
    return bits;
}

int rankClass(uint32_t rank) { return rank == 1 ? 1 : rank == 2 ? 2 : 0; }

// Codes the stream and checks it decodes; returns coded bits / ideal bits.
double efficiency(const std::vector<Coded>& ranks, int extraContexts,
                  const std::map<int, std::map<uint32_t, uint64_t>>& counts, const char* name) {
    const std::vector<uint8_t> bytes = encodeAll(ranks, extraContexts);
    const double ideal = empiricalEntropyBits(counts);
    const double ratio = double(bytes.size()) * 8 / ideal;
    std::printf("[ efficiency ] %s: %zu ranks, %zu bytes, ideal %.1f bytes, ratio %.4f\n", name,
                ranks.size(), bytes.size(), ideal / 8, ratio);
    expectRoundTrip(ranks, extraContexts);
    return ratio;
}

TEST(RankCoder, ExtremeValuesRoundTrip) {
    std::vector<Coded> ranks;
    const uint32_t special[] = {0, 1, 2, 3, 22, 23, 24, 25, 26, 27, 100, 0x7FFFFFFFu, 0x80000000u,
                                0xFFFFFFE7u, 0xFFFFFFE8u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    for (uint32_t r : special) ranks.push_back({r, 0});
    for (int bit = 0; bit < 32; ++bit)
        for (int64_t delta = -1; delta <= 1; ++delta) {
            const int64_t r = (int64_t(1) << bit) + delta;
            if (r >= 0 && r <= int64_t(UINT32_MAX)) ranks.push_back({uint32_t(r), 0});
        }
    for (uint32_t r : special) ranks.push_back({r, 0});
    expectRoundTrip(ranks, 1);
}

TEST(RankCoder, RandomValuesInManyContextsRoundTrip) {
    std::mt19937 rng(11);
    for (int extraContexts : {1, 2, 7}) {
        std::vector<Coded> ranks;
        for (int i = 0; i < 50000; ++i) {
            uint32_t rank;
            switch (rng() % 4) {
            case 0: rank = rng(); break;                        // any uint32
            case 1: rank = rng() >> (rng() % 32); break;        // every bit length
            default: rank = rng() % 3; break;                   // the common ranks
            }
            ranks.push_back({rank, int(rng() % uint32_t(extraContexts))});
        }
        expectRoundTrip(ranks, extraContexts);
    }
}

TEST(RankCoder, EmptyStreamRoundTrips) {
    drm::RankEncoder encoder;
    const std::vector<uint8_t> bytes = encoder.finish();
    EXPECT_LE(bytes.size(), 1u);
    drm::RankDecoder decoder(bytes.data(), bytes.size());
    EXPECT_EQ(decoder.bytesPastEnd(), 0u);
}

TEST(RankCoder, TypicalStreamIsWithinThreePercentOfEntropy) {
    std::mt19937 rng(12);
    std::discrete_distribution<uint32_t> pick = typicalRanks();
    std::vector<Coded> ranks;
    std::map<int, std::map<uint32_t, uint64_t>> counts;
    for (int i = 0; i < 100000; ++i) {
        const uint32_t r = pick(rng);
        ranks.push_back({r, 0});
        ++counts[0][r];
    }
    EXPECT_LT(efficiency(ranks, 1, counts, "i.i.d. typical"), 1.03);
}

TEST(RankCoder, PreviousRankContextIsExploited) {
    // After a 2 another 2 is far likelier than after a 1, as along the
    // strips of a regular mesh: the coder should approach the conditional
    // entropy, which is well below the order-0 entropy of the same stream.
    std::mt19937 rng(13);
    std::discrete_distribution<uint32_t> afterOther({0.03, 0.80, 0.15, 0.02});
    std::discrete_distribution<uint32_t> afterOne({0.002, 0.95, 0.045, 0.003});
    std::discrete_distribution<uint32_t> afterTwo({0.01, 0.55, 0.42, 0.02});
    std::vector<Coded> ranks;
    std::map<int, std::map<uint32_t, uint64_t>> conditional, order0;
    int previous = 0;
    for (int i = 0; i < 100000; ++i) {
        const uint32_t r = previous == 1 ? afterOne(rng) : previous == 2 ? afterTwo(rng) : afterOther(rng);
        ranks.push_back({r, 0});
        ++conditional[previous][r];
        ++order0[0][r];
        previous = rankClass(r);
    }
    EXPECT_LT(efficiency(ranks, 1, conditional, "order-1 Markov"), 1.03);
    EXPECT_LT(empiricalEntropyBits(conditional), 0.95 * empiricalEntropyBits(order0));
}

TEST(RankCoder, CallerContextIsExploited) {
    // Two caller contexts with different statistics, interleaved at random.
    std::mt19937 rng(14);
    std::discrete_distribution<uint32_t> pick[2] = {
        std::discrete_distribution<uint32_t>({0.001, 0.98, 0.019}),
        std::discrete_distribution<uint32_t>({0.02, 0.70, 0.20, 0.05, 0.03})};
    std::vector<Coded> ranks;
    std::map<int, std::map<uint32_t, uint64_t>> counts;
    int previous = 0;
    for (int i = 0; i < 100000; ++i) {
        const int context = rng() % 4 == 0 ? 1 : 0;
        const uint32_t r = pick[context](rng);
        ranks.push_back({r, context});
        ++counts[previous * 2 + context][r];
        previous = rankClass(r);
    }
    EXPECT_LT(efficiency(ranks, 2, counts, "two caller contexts"), 1.03);
}

TEST(RankCoder, EscapedRanksCostTheirExpGolombLength) {
    // Ranks spread over a wide range all take the escape: the cost per rank
    // should stay near the entropy of their bit length plus the raw bits.
    std::mt19937 rng(15);
    std::vector<Coded> ranks;
    uint64_t rawBits = 0;
    for (int i = 0; i < 20000; ++i) {
        const int length = 1 + int(rng() % 20);
        const uint64_t w = (uint64_t(1) << (length - 1)) | (rng() & ((uint64_t(1) << (length - 1)) - 1));
        ranks.push_back({uint32_t(w - 1 + drm::kRankDirectSymbols), 0});
        rawBits += uint64_t(length - 1);
    }
    const std::vector<uint8_t> bytes = encodeAll(ranks, 1);
    // Raw bits, plus log2(20) bits for the length, plus a little for the escape symbol.
    const double bound = double(rawBits) / 8 + ranks.size() * (std::log2(20.0) + 0.2) / 8;
    std::printf("[ efficiency ] escaped ranks: %zu bytes, bound %.0f bytes\n", bytes.size(), bound);
    EXPECT_LT(double(bytes.size()), bound);
    expectRoundTrip(ranks, 1);
}

TEST(RankCoder, TruncatedStreamIsDetected) {
    std::mt19937 rng(16);
    std::discrete_distribution<uint32_t> pick = typicalRanks();
    std::vector<uint32_t> ranks;
    drm::RankEncoder encoder;
    for (int i = 0; i < 20000; ++i) {
        ranks.push_back(pick(rng));
        encoder.put(ranks.back());
    }
    const std::vector<uint8_t> bytes = encoder.finish();
    ASSERT_GT(bytes.size(), 20u);
    for (size_t keep : {size_t(0), bytes.size() / 2, bytes.size() - 1}) {
        drm::RankDecoder decoder(bytes.data(), keep);
        for (size_t i = 0; i < ranks.size(); ++i) {
            try {
                decoder.get();
            } catch (const drm::Error&) {
                break;  // acceptable: the garbage decoded to an impossible rank
            }
        }
        EXPECT_GT(decoder.bytesPastEnd(), 0u) << "kept " << keep << " of " << bytes.size();
    }
}

TEST(RankCoder, GarbageDecodesOrThrowsError) {
    std::mt19937 rng(17);
    int threw = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<uint8_t> garbage(rng() % 200);
        for (uint8_t& b : garbage) b = uint8_t(rng() % 2 == 0 ? 0xFF : rng());
        const int extraContexts = 1 + int(rng() % 3);
        drm::RankDecoder decoder(garbage.data(), garbage.size(), extraContexts);
        try {
            for (int i = 0; i < 5000; ++i) decoder.get(int(rng() % uint32_t(extraContexts)));
        } catch (const drm::Error& e) {
            EXPECT_EQ(e.kind(), drm::ErrorKind::Corrupt) << e.what();
            ++threw;
        }
    }
    std::printf("[ garbage ] %d of 300 garbage streams held an impossible rank\n", threw);
}

TEST(RankCoder, ImpossibleRankThrows) {
    // All-0xFF input puts the coded value at the top of every table: the
    // escape symbol, the longest bit length, all-ones bits, which is a rank
    // past UINT32_MAX.
    const std::vector<uint8_t> ones(64, 0xFF);
    drm::RankDecoder decoder(ones.data(), ones.size());
    EXPECT_THROW(decoder.get(), drm::Error);
}

// The boundary flags: rank 0 as a flag before the rank, in a
// class per edge. Any rank in any context and class round-trips; a stream
// whose boundary edges follow their class (as borders do) costs less than
// the same ranks without the flags; and garbage decodes or throws Corrupt
// (among others for a rank 0 after a "no").
struct Flagged {
    uint32_t rank;
    int context, boundaryClass;
};

std::vector<uint8_t> encodeFlagged(const std::vector<Flagged>& ranks, int extraContexts, bool flags) {
    drm::RankEncoder encoder(extraContexts, flags);
    for (const Flagged& c : ranks) encoder.put(c.rank, c.context, c.boundaryClass);
    return encoder.finish();
}

TEST(RankCoder, BoundaryFlagsRoundTrip) {
    std::mt19937 rng(23);
    std::vector<Flagged> ranks;
    for (int i = 0; i < 20000; ++i) {
        const uint32_t r = rng() % 10 == 0 ? 0u : rng() % 50 == 0 ? uint32_t(rng()) : 1 + rng() % 5;
        ranks.push_back({r, int(rng() % 3), int(rng() % uint32_t(drm::kBoundaryClasses))});
    }
    const std::vector<uint8_t> bytes = encodeFlagged(ranks, 3, true);
    drm::RankDecoder decoder(bytes.data(), bytes.size(), 3, true);
    for (size_t i = 0; i < ranks.size(); ++i)
        ASSERT_EQ(decoder.get(ranks[i].context, ranks[i].boundaryClass), ranks[i].rank) << "rank " << i;
    EXPECT_EQ(decoder.bytesPastEnd(), 0u);
}

TEST(RankCoder, BoundaryFlagsPayWhereTheClassTellsBoundaries) {
    std::mt19937 rng(29);
    std::discrete_distribution<uint32_t> inner({0.0, 0.93, 0.06, 0.007, 0.002, 0.001});
    std::vector<Flagged> ranks;
    for (int i = 0; i < 50000; ++i) {
        // 2 % of the edges in class 8 (nothing ahead, both fans on a
        // boundary): nearly all boundary edges; elsewhere 1 in 500.
        const bool border = rng() % 50 == 0;
        const bool boundary = border ? rng() % 20 != 0 : rng() % 500 == 0;
        ranks.push_back({boundary ? 0u : inner(rng), 0, border ? 8 : 0});
    }
    const size_t flagged = encodeFlagged(ranks, 1, true).size(), plain = encodeFlagged(ranks, 1, false).size();
    std::printf("[ boundary flags ] %zu bytes with, %zu without\n", flagged, plain);
    EXPECT_LT(double(flagged), 0.9 * double(plain));
}

TEST(RankCoder, BoundaryFlagGarbageDecodesOrThrowsCorrupt) {
    std::mt19937 rng(31);
    int threw = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<uint8_t> garbage(rng() % 200);
        for (uint8_t& b : garbage) b = uint8_t(rng());
        drm::RankDecoder decoder(garbage.data(), garbage.size(), 2, true);
        try {
            for (int i = 0; i < 5000; ++i) decoder.get(int(rng() % 2), int(rng() % uint32_t(drm::kBoundaryClasses)));
        } catch (const drm::Error& e) {
            EXPECT_EQ(e.kind(), drm::ErrorKind::Corrupt) << e.what();
            ++threw;
        }
    }
    EXPECT_GT(threw, 0);
}

// The decoder's two steps (getBoundaryFlag, then getRank unless the edge
// is a boundary) read what get() reads, ranks and refusals alike, on
// streams as written and on garbage.
TEST(RankCoder, TwoStepsReadWhatGetReads) {
    std::mt19937 rng(37);
    auto read = [](drm::RankDecoder& d, bool twoSteps, int context, int boundaryClass) {
        if (!twoSteps) return d.get(context, boundaryClass);
        return d.getBoundaryFlag(boundaryClass) ? 0u : d.getRank(context);
    };
    int threw = 0;
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<uint8_t> bytes;
        if (trial % 2 == 0) {
            std::vector<Flagged> ranks;
            for (int i = 0; i < 500; ++i)
                ranks.push_back({rng() % 8 == 0 ? 0u : 1 + rng() % 30, int(rng() % 2), int(rng() % uint32_t(drm::kBoundaryClasses))});
            bytes = encodeFlagged(ranks, 2, true);
        } else {
            bytes.resize(rng() % 200);
            for (uint8_t& b : bytes) b = uint8_t(rng());
        }
        std::vector<std::pair<int, int>> contexts(2000);
        for (auto& c : contexts) c = {int(rng() % 2), int(rng() % uint32_t(drm::kBoundaryClasses))};
        std::vector<uint32_t> got[2];
        std::string refused[2];
        for (int way = 0; way < 2; ++way) {
            drm::RankDecoder decoder(bytes.data(), bytes.size(), 2, true);
            try {
                for (const auto& c : contexts) got[way].push_back(read(decoder, way == 1, c.first, c.second));
            } catch (const drm::Error& e) {
                EXPECT_EQ(e.kind(), drm::ErrorKind::Corrupt) << e.what();
                refused[way] = e.what();
            }
        }
        EXPECT_EQ(got[0], got[1]) << "trial " << trial;
        EXPECT_EQ(refused[0], refused[1]) << "trial " << trial;
        threw += refused[1].empty() ? 0 : 1;
    }
    EXPECT_GT(threw, 0);
}

TEST(RankCoder, BadContextsThrow) {
    EXPECT_THROW(drm::RankEncoder(0), drm::Error);
    EXPECT_THROW(drm::RankDecoder(nullptr, 0, 0), drm::Error);
    drm::RankEncoder encoder(2);
    EXPECT_THROW(encoder.put(1, 2), drm::Error);
    EXPECT_THROW(encoder.put(1, -1), drm::Error);
    drm::RankDecoder decoder(nullptr, 0, 2);
    EXPECT_THROW(decoder.get(2), drm::Error);
    drm::RankEncoder flagged(1, true);
    EXPECT_THROW(flagged.put(1, 0, drm::kBoundaryClasses), drm::Error);
    EXPECT_THROW(flagged.put(1, 0, -1), drm::Error);
}

}  // namespace
