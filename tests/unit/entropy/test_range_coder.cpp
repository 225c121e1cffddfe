// The range coder alone: exact round trips of arbitrary frequency tables,
// carry handling, the byte budget of flushing, and safety on bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "entropy/range_coder.h"

namespace {

struct Symbol {
    uint32_t cum, freq, total;
};

// A random slot table per symbol: totals from 1 to the maximum, and slots
// anywhere in it, including the first, the last and the whole table.
std::vector<Symbol> randomSymbols(std::mt19937& rng, size_t n) {
    std::vector<Symbol> symbols;
    for (size_t i = 0; i < n; ++i) {
        uint32_t total;
        switch (rng() % 4) {
        case 0: total = drm::kRangeCoderMaxTotal; break;
        case 1: total = 1 + rng() % 4; break;
        default: total = 1 + rng() % drm::kRangeCoderMaxTotal; break;
        }
        const uint32_t cum = rng() % total;
        const uint32_t freq = 1 + rng() % (total - cum);
        symbols.push_back({cum, freq, total});
    }
    return symbols;
}

std::vector<uint8_t> encodeAll(const std::vector<Symbol>& symbols) {
    drm::RangeEncoder encoder;
    for (const Symbol& s : symbols) encoder.encode(s.cum, s.freq, s.total);
    return encoder.finish();
}

// Decodes symbols against their own tables; true if every one comes back.
bool decodesTo(const std::vector<uint8_t>& bytes, const std::vector<Symbol>& symbols) {
    drm::RangeDecoder decoder(bytes.data(), bytes.size());
    for (const Symbol& s : symbols) {
        const uint32_t slot = decoder.decodeFreq(s.total);
        if (slot < s.cum || slot >= s.cum + s.freq) return false;
        decoder.consume(s.cum, s.freq, s.total);
    }
    return decoder.bytesPastEnd() == 0;
}

TEST(RangeCoder, RandomTablesRoundTrip) {
    std::mt19937 rng(1);
    for (int trial = 0; trial < 200; ++trial) {
        const std::vector<Symbol> symbols = randomSymbols(rng, 1 + rng() % 2000);
        EXPECT_TRUE(decodesTo(encodeAll(symbols), symbols)) << "trial " << trial;
    }
}

TEST(RangeCoder, EmptyStreamIsOneByte) {
    drm::RangeEncoder encoder;
    const std::vector<uint8_t> bytes = encoder.finish();
    EXPECT_EQ(bytes.size(), 1u);
    drm::RangeDecoder decoder(bytes.data(), bytes.size());
    EXPECT_EQ(decoder.bytesPastEnd(), 0u);
}

TEST(RangeCoder, LongRunsOfFFAndCarriesRoundTrip) {
    // Symbols at the very top of the table push low towards 2^32, which
    // produces runs of 0xFF held back for a carry; symbols just below the
    // top then make those carries happen.
    std::mt19937 rng(2);
    const uint32_t total = drm::kRangeCoderMaxTotal;
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<Symbol> symbols;
        for (int i = 0; i < 3000; ++i) {
            if (rng() % 8 != 0)
                symbols.push_back({total - 1, 1, total});
            else
                symbols.push_back({total - 2 - uint32_t(rng() % 8), 1, total});
        }
        const std::vector<uint8_t> bytes = encodeAll(symbols);
        size_t longestFF = 0, run = 0;
        for (uint8_t b : bytes) {
            run = b == 0xFF ? run + 1 : 0;
            longestFF = std::max(longestFF, run);
        }
        EXPECT_GE(longestFF, 3u);
        EXPECT_TRUE(decodesTo(bytes, symbols)) << "trial " << trial;
    }
}

// bytesAtLeast never shrinks while symbols are coded and never exceeds
// what finish() hands over, also through runs of 0xFF held back for a
// carry (the encoder stops a losing way of coding on it).
TEST(RangeCoder, BytesAtLeastIsAFloorThatOnlyGrows) {
    std::mt19937 rng(3);
    const uint32_t total = drm::kRangeCoderMaxTotal;
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<Symbol> symbols = trial % 2 ? randomSymbols(rng, 2000) : std::vector<Symbol>();
        for (int i = 0; trial % 2 == 0 && i < 2000; ++i)  // runs of 0xFF and carries, as above
            symbols.push_back(rng() % 8 ? Symbol{total - 1, 1, total} : Symbol{total - 2 - uint32_t(rng() % 8), 1, total});
        drm::RangeEncoder encoder;
        size_t floor = encoder.bytesAtLeast(), grew = 0;
        for (const Symbol& s : symbols) {
            encoder.encode(s.cum, s.freq, s.total);
            ASSERT_GE(encoder.bytesAtLeast(), floor) << "trial " << trial;
            grew += encoder.bytesAtLeast() > floor ? 1 : 0;
            floor = encoder.bytesAtLeast();
        }
        const size_t size = encoder.finish().size();
        EXPECT_LE(floor, size) << "trial " << trial;
        EXPECT_GE(floor + 2, size) << "trial " << trial;  // and close to it
        EXPECT_GT(grew, 0u);
    }
}

TEST(RangeCoder, CertainSymbolsCostNothing) {
    drm::RangeEncoder encoder;
    for (int i = 0; i < 100000; ++i) encoder.encode(0, 7, 7);
    EXPECT_EQ(encoder.finish().size(), 1u);
}

TEST(RangeCoder, BitsRoundTripAndCostOneBitEach) {
    std::mt19937 rng(3);
    std::vector<std::pair<uint32_t, int>> values;
    uint64_t totalBits = 0;
    for (int count = 0; count <= 16; ++count) {
        values.push_back({0, count});
        values.push_back({(uint32_t(1) << count) - 1, count});
    }
    for (int i = 0; i < 100000; ++i) {
        const int count = int(rng() % 17);
        values.push_back({rng() & ((uint32_t(1) << count) - 1), count});
    }
    drm::RangeEncoder encoder;
    for (const auto& v : values) {
        encoder.encodeBits(v.first, v.second);
        totalBits += uint64_t(v.second);
    }
    const std::vector<uint8_t> bytes = encoder.finish();
    // Within 0.01% of the raw size (range truncation loss) plus a byte or two of flush.
    EXPECT_LE(bytes.size(), totalBits / 8 + totalBits / 8 / 10000 + 2);
    EXPECT_GE(bytes.size(), totalBits / 8);

    drm::RangeDecoder decoder(bytes.data(), bytes.size());
    for (size_t i = 0; i < values.size(); ++i)
        ASSERT_EQ(decoder.decodeBits(values[i].second), values[i].first) << "value " << i;
    EXPECT_EQ(decoder.bytesPastEnd(), 0u);
}

TEST(RangeCoder, EncodeBitsIgnoresHighBits) {
    drm::RangeEncoder encoder;
    encoder.encodeBits(0xFFFF0005u, 4);
    encoder.encodeBits(0x12345678u, 0);
    encoder.encodeBits(0xABCDu, 16);
    const std::vector<uint8_t> bytes = encoder.finish();
    drm::RangeDecoder decoder(bytes.data(), bytes.size());
    EXPECT_EQ(decoder.decodeBits(4), 5u);
    EXPECT_EQ(decoder.decodeBits(0), 0u);
    EXPECT_EQ(decoder.decodeBits(16), 0xABCDu);
}

TEST(RangeCoder, TruncationIsCountedExactly) {
    std::mt19937 rng(4);
    const std::vector<Symbol> symbols = randomSymbols(rng, 5000);
    const std::vector<uint8_t> bytes = encodeAll(symbols);
    ASSERT_GT(bytes.size(), 100u);
    for (size_t cut : {size_t(1), size_t(2), size_t(10), bytes.size()}) {
        drm::RangeDecoder decoder(bytes.data(), bytes.size() - cut);
        for (const Symbol& s : symbols) {
            const uint32_t slot = decoder.decodeFreq(s.total);
            ASSERT_LT(slot, s.total);
            // Follow the true symbols so the byte count matches the intact run.
            decoder.consume(s.cum, s.freq, s.total);
        }
        EXPECT_EQ(decoder.bytesPastEnd(), cut);
    }
}

TEST(RangeCoder, GarbageDecodesToInRangeSlots) {
    std::mt19937 rng(5);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<uint8_t> garbage(rng() % 64);
        for (uint8_t& b : garbage) b = uint8_t(rng() % 3 == 0 ? 0xFF : rng());
        drm::RangeDecoder decoder(garbage.empty() ? nullptr : garbage.data(), garbage.size());
        for (int i = 0; i < 2000; ++i) {
            const uint32_t total = 1 + rng() % drm::kRangeCoderMaxTotal;
            const uint32_t slot = decoder.decodeFreq(total);
            ASSERT_LT(slot, total);
            // Consume a symbol that owns the slot, as a model would.
            const uint32_t cum = slot - std::min<uint32_t>(slot, rng() % 4);
            decoder.consume(cum, slot - cum + 1, total);
            ASSERT_LT(decoder.decodeBits(3), 8u);
        }
    }
}

// A log replayed unit by unit, with other calls made between the units,
// gives the bytes of making every call directly in that order: symbols of
// any table (the binary ones over 4096 kept in one word, totals up to the
// maximum, whose 17th bits need the long form), plain bits of any width
// up to 64, and empty units.
TEST(CodingLog, ReplayedUnitsCodeAsTheCallsThemselves) {
    std::mt19937 rng(6);
    for (int trial = 0; trial < 100; ++trial) {
        drm::RangeEncoder direct, replayed;
        drm::CodingLog log;
        std::vector<Symbol> between;  // after each unit
        const int units = 1 + int(rng() % 200);
        for (int u = 0; u < units; ++u) {
            for (int call = int(rng() % 12); call > 0; --call) {
                if (rng() % 3 == 0) {
                    const int count = int(rng() % 65);
                    const uint64_t value = uint64_t(rng()) << 32 | rng();
                    direct.encodeWideBits(value, count);
                    log.encodeWideBits(value, count);
                } else {
                    Symbol s;
                    if (rng() % 2 == 0) {
                        const uint32_t p1 = 1 + rng() % 4095;
                        s = rng() % 2 ? Symbol{4096 - p1, p1, 4096} : Symbol{0, 4096 - p1, 4096};
                    } else {
                        s = randomSymbols(rng, 1)[0];
                    }
                    direct.encode(s.cum, s.freq, s.total);
                    log.encode(s.cum, s.freq, s.total);
                }
            }
            log.endUnit();
            between.push_back(randomSymbols(rng, 1)[0]);
            direct.encode(between.back().cum, between.back().freq, between.back().total);
        }
        size_t at = 0;
        for (const Symbol& s : between) {
            at = log.replayInto(replayed, at);
            replayed.encode(s.cum, s.freq, s.total);
        }
        EXPECT_EQ(at, log.size());
        EXPECT_EQ(replayed.finish(), direct.finish()) << "trial " << trial;
    }
}

// bitsSoFar measures what has been coded: over any stretch of symbols it
// grows by their information (-log2 of each probability) to within the
// coder's rounding, and the finished stream is as long as it says, to
// within the bytes a flush adds or leaves off.
TEST(RangeCoder, BitsSoFarIsTheInformationCoded) {
    std::mt19937 rng(8);
    const std::vector<Symbol> symbols = randomSymbols(rng, 20000);
    drm::RangeEncoder encoder;
    EXPECT_NEAR(encoder.bitsSoFar(), 0.0, 1e-6);
    double information = 0, stretch = 0, stretchStart = 0;
    for (size_t i = 0; i < symbols.size(); ++i) {
        const Symbol& s = symbols[i];
        encoder.encode(s.cum, s.freq, s.total);
        const double bits = std::log2(double(s.total) / double(s.freq));
        information += bits;
        stretch += bits;
        if (i % 1000 == 999) {
            EXPECT_NEAR(encoder.bitsSoFar() - stretchStart, stretch, 0.5 + 0.001 * stretch) << "symbols to " << i;
            stretchStart = encoder.bitsSoFar();
            stretch = 0;
        }
    }
    EXPECT_NEAR(encoder.bitsSoFar(), information, 1.0 + 0.001 * information);
    const double said = encoder.bitsSoFar();
    EXPECT_NEAR(8.0 * double(encoder.finish().size()), said, 32.0);
}

}  // namespace
