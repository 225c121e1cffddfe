// The functions through which the tree coder's encoder writes and its
// decoder reads one vertex (geometry/tree/tree_coding.h), run through a
// Writer and then a Reader with states kept alike: a walk of children
// comes back point for point (choices as flags or as one symbol, the local
// frame allowed or not, the encoder's own pick or one it is given), both
// states agreeing on the frame; child counts come back, escaped ones
// included; a choice past the candidates is refused; and the magnitude
// contexts of the edge from the parent follow the local spacing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "entropy/bit_model.h"
#include "entropy/range_coder.h"
#include "geometry/tree/tree_coding.h"

namespace drm {
namespace tree_coding {
namespace {

// Points of a wavy sheet, and each one's parent: the nearest earlier one
// of a few tried (a tree the coder could have grown).
struct Walk {
    std::vector<GridPoint> points;
    std::vector<uint32_t> parents;
};
Walk sheet(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    Walk w;
    for (int i = 0; i < n; ++i) {
        const int32_t x = 500 + int32_t(rng() % 200), y = 500 + int32_t(rng() % 200);
        w.points.push_back({x, y, 500 + (x / 7 + y / 11) % 9});
        uint32_t parent = kNoVertex;
        int64_t best = INT64_MAX;
        for (int k = 0; k < i; ++k) {
            const int64_t d = distance2(w.points[size_t(k)], w.points.back());
            if (d < best) best = d, parent = uint32_t(k);
        }
        w.parents.push_back(parent);
    }
    return w;
}

void expectWalkRoundTrips(bool flags, bool frame, bool givePick) {
    const Walk w = sheet(400, flags * 2 + frame);
    CodingState encoder(4, flags, frame), decoder(4, flags, frame);
    RangeEncoder out;
    Writer writer{out};
    std::mt19937 rng(19);
    for (uint32_t v = 0; v < w.points.size(); ++v) {
        encoder.begin(w.parents[v]);
        if (w.parents[v] == kNoVertex) {
            encoder.place(v, w.points[v]);
            continue;
        }
        const Predictions p = predict(encoder, v, w.parents[v]);
        const uint32_t pick = givePick ? uint32_t(rng() % uint32_t(p.count)) : kNotChosen;
        // A given pick that repeats an earlier candidate is that one.
        uint32_t chosen = pick;
        if (pick != kNotChosen)
            while (repeatsEarlier(p, int(chosen))) --chosen;
        const GridPoint at = codeChild(writer, encoder, v, w.parents[v], p, w.points[v], chosen);
        ASSERT_TRUE(at.x == w.points[v].x && at.y == w.points[v].y && at.z == w.points[v].z) << v;
        if (pick != kNotChosen) ASSERT_EQ(encoder.previousChoice, chosen);
        encoder.place(v, at);
    }
    const std::vector<uint8_t> bytes = out.finish();
    RangeDecoder in(bytes.data(), bytes.size());
    Reader reader{in};
    for (uint32_t v = 0; v < w.points.size(); ++v) {
        decoder.begin(w.parents[v]);
        if (w.parents[v] == kNoVertex) {
            decoder.place(v, w.points[v]);
            continue;
        }
        const GridPoint at = codeChild(reader, decoder, v, w.parents[v], GridPoint{});
        ASSERT_TRUE(at.x == w.points[v].x && at.y == w.points[v].y && at.z == w.points[v].z) << "vertex " << v;
        decoder.place(v, at);
    }
    EXPECT_EQ(in.bytesPastEnd(), 0u);
    EXPECT_EQ(decoder.framedResiduals, encoder.framedResiduals);
    EXPECT_EQ(decoder.frameScore, encoder.frameScore);
    if (!frame) EXPECT_EQ(encoder.framedResiduals, 0u);
}

TEST(TreeCoding, AWalkOfChildrenRoundTrips) {
    for (bool flags : {true, false})
        for (bool frame : {false, true})
            for (bool givePick : {false, true}) {
                SCOPED_TRACE(std::string(flags ? "flags" : "one symbol") + (frame ? ", frame" : "") +
                             (givePick ? ", given picks" : ""));
                expectWalkRoundTrips(flags, frame, givePick);
            }
}

TEST(TreeCoding, ChildCountsRoundTripEscapedOnesIncluded) {
    const std::vector<uint32_t> counts = {0, 1, 2, 7, 8, 9, 15, 100, 5, 1u << 20, 3, 0xFFFFFFFFu - 1};
    CodingState encoder(4, false, false), decoder(4, false, false);
    RangeEncoder out;
    Writer writer{out};
    for (uint32_t v = 0; v < counts.size(); ++v) {
        encoder.begin(v == 0 ? kNoVertex : v - 1);
        EXPECT_EQ(codeChildCount(writer, encoder, v, counts[v]), counts[v]);
        EXPECT_EQ(encoder.childCountOf.back(), std::min(counts[v], kDirectChildCounts));  // 8: escaped
    }
    const std::vector<uint8_t> bytes = out.finish();
    RangeDecoder in(bytes.data(), bytes.size());
    Reader reader{in};
    for (uint32_t v = 0; v < counts.size(); ++v) {
        decoder.begin(v == 0 ? kNoVertex : v - 1);
        EXPECT_EQ(codeChildCount(reader, decoder, v, 0), counts[v]) << v;
    }
    EXPECT_EQ(decoder.childCountOf, encoder.childCountOf);
}

TEST(TreeCoding, AChoicePastTheCandidatesIsRefused) {
    // One symbol naming candidate 17 where only two exist.
    CodingState encoder(4, false, false);
    Predictions many;
    for (int c = 0; c < kMaxCandidates; ++c) many.add(GridPoint{c, 0, 0});
    RangeEncoder out;
    Writer writer{out};
    codeChoice(writer, encoder, many, kMaxCandidates - 1);
    const std::vector<uint8_t> bytes = out.finish();
    CodingState decoder(4, false, false);
    Predictions two;
    two.add(GridPoint{0, 0, 0});
    two.add(GridPoint{1, 0, 0});
    RangeDecoder in(bytes.data(), bytes.size());
    Reader reader{in};
    try {
        codeChoice(reader, decoder, two, 0);
        FAIL() << "a choice past the candidates was taken";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Corrupt);
        EXPECT_STREQ(e.what(), "corrupt file: a geometry predictor choice is out of range");
    }
}

TEST(TreeCoding, TheEdgeFromTheParentTakesItsContextsFromTheSpacing) {
    CodingState s(8, true, false);
    const GridPoint points[3] = {{100, 100, 100}, {140, 100, 100}, {100, 130, 100}};
    for (uint32_t v = 0; v < 3; ++v) {
        s.begin(v == 0 ? kNoVertex : 0);
        s.place(v, points[v]);
    }
    s.begin(1);
    const Predictions p = predict(s, 3, 1);
    ASSERT_GT(p.spacing2, 0);
    int contexts[kResidualGroups][3];
    magnitudeContexts(s, p, 3, 1, contexts);
    const int length = bitLength(uint64_t(p.spacing2));
    const auto clamped = [](int c) { return std::max(0, std::min(c, kMagnitudeContexts - 1)); };
    EXPECT_EQ(contexts[0][0], clamped(length - 2));
    EXPECT_EQ(contexts[0][1], clamped(length - 2));
    EXPECT_EQ(contexts[0][2], clamped(length - 6));
    for (int a = 0; a < 3; ++a) EXPECT_EQ(contexts[1][a], magnitudeContext(s, 3, 1, a));
    // No near points: both groups from the residuals around.
    CodingState lone(8, true, false);
    lone.begin(kNoVertex);
    lone.place(0, GridPoint{5, 5, 5});
    lone.begin(0);
    const Predictions q = predict(lone, 1, 0);
    magnitudeContexts(lone, q, 1, 0, contexts);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(contexts[0][a], magnitudeContext(lone, 1, 0, a));
}

}  // namespace
}  // namespace tree_coding
}  // namespace drm
