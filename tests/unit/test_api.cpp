// The library's small public helpers (api.cpp): the names of error kinds,
// predictors, coders and levers and their parsers, which must be each
// other's inverse and refuse what they do not know with an InvalidInput
// Error naming the word and the choices; the rank palette's clamping; the
// per-vertex figures of Stats; and the sentence describeRepairs makes.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "drmcodec/drmcodec.h"

namespace {

// The message of the InvalidInput drm::Error f throws, or "" if none.
template <class F>
std::string refusal(F f) {
    try {
        f();
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "nothing refused";
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ErrorKinds, NamesAreDistinct) {
    EXPECT_STREQ(drm::errorKindName(drm::ErrorKind::Corrupt), "corrupt");
    EXPECT_STRNE(drm::errorKindName(drm::ErrorKind::Io), drm::errorKindName(drm::ErrorKind::Internal));
    std::set<std::string> names;
    for (drm::ErrorKind k : {drm::ErrorKind::InvalidInput, drm::ErrorKind::Corrupt, drm::ErrorKind::Unsupported,
                             drm::ErrorKind::Cancelled, drm::ErrorKind::Io, drm::ErrorKind::Internal})
        EXPECT_TRUE(names.insert(drm::errorKindName(k)).second) << drm::errorKindName(k);
    // drmcodec.h's list, word for word.
    EXPECT_EQ(names, (std::set<std::string>{"invalid input", "corrupt", "unsupported", "cancelled", "i/o", "internal"}));
}

TEST(ErrorKinds, AnErrorWithoutAKindIsInvalidInput) {
    const drm::Error e("bad option");
    EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput);
    EXPECT_STREQ(e.what(), "bad option");
}

TEST(Limits, LeverNamesParseBack) {
    for (int l = 0; l < drm::kLeverCount; ++l) EXPECT_NO_THROW(drm::parseLevers(drm::leverName(l)));
    EXPECT_EQ(drm::leverName(drm::kLeverCount), nullptr);
    EXPECT_EQ(drm::leverName(-1), nullptr);
}

TEST(Names, PredictorsAndCodersParseBackTheirNames) {
    for (drm::Predictor p : {drm::Predictor::Auto, drm::Predictor::Parallelogram, drm::Predictor::Midpoint})
        EXPECT_EQ(drm::parsePredictor(drm::predictorName(p)), p);
    for (drm::ConnectivityCoder c :
         {drm::ConnectivityCoder::Auto, drm::ConnectivityCoder::Ranks, drm::ConnectivityCoder::Topological})
        EXPECT_EQ(drm::parseConnectivityCoder(drm::connectivityCoderName(c)), c);
    for (drm::GeometryCoder g : {drm::GeometryCoder::Auto, drm::GeometryCoder::Raw, drm::GeometryCoder::SpanningTree,
                                 drm::GeometryCoder::Refine, drm::GeometryCoder::Sorted})
        EXPECT_EQ(drm::parseGeometryCoder(drm::geometryCoderName(g)), g);
    // The names drmcodec.h documents for the parsers.
    EXPECT_EQ(drm::parseGeometryCoder("tree"), drm::GeometryCoder::SpanningTree);
    EXPECT_EQ(drm::parsePredictor("midpoint"), drm::Predictor::Midpoint);
    EXPECT_EQ(drm::parseConnectivityCoder("topological"), drm::ConnectivityCoder::Topological);
}

TEST(Names, UnknownNamesAreRefusedWithTheChoices) {
    const std::string predictor = refusal([] { drm::parsePredictor("Midpoint"); });  // case matters
    EXPECT_TRUE(contains(predictor, "'Midpoint'")) << predictor;
    EXPECT_TRUE(contains(predictor, "parallelogram")) << predictor;
    const std::string connectivity = refusal([] { drm::parseConnectivityCoder(""); });
    EXPECT_TRUE(contains(connectivity, "ranks")) << connectivity;
    // Every geometry coder's name is offered, auto first.
    const std::string geometry = refusal([] { drm::parseGeometryCoder("octree"); });
    EXPECT_TRUE(contains(geometry, "'octree'")) << geometry;
    EXPECT_TRUE(contains(geometry, "(use auto, ")) << geometry;
    for (drm::GeometryCoder g :
         {drm::GeometryCoder::Raw, drm::GeometryCoder::SpanningTree, drm::GeometryCoder::Refine, drm::GeometryCoder::Sorted})
        EXPECT_TRUE(contains(geometry, drm::geometryCoderName(g))) << geometry;
    const std::string lever = refusal([] { drm::parseLevers("filter,,gap"); });  // an empty name
    EXPECT_TRUE(contains(lever, "unknown lever ''")) << lever;
    for (int l = 0; l < drm::kLeverCount; ++l) EXPECT_TRUE(contains(lever, drm::leverName(l))) << lever;
}

TEST(Levers, EverySubsetNamesAndParsesBack) {
    for (unsigned bits = 0; bits < (1u << drm::kLeverCount); ++bits) {
        drm::Levers l = drm::Levers::none();
        bool* fields[] = {&l.topologicalFilter, &l.gapClosing, &l.confidenceContext,
                          &l.angleOrder,        &l.frontNeighbours, &l.boundaryFlag};
        for (int k = 0; k < drm::kLeverCount; ++k) *fields[k] = (bits >> k) & 1;
        const std::string name = drm::leversName(l);
        if (bits == 0) EXPECT_EQ(name, "none");
        if (bits + 1 == (1u << drm::kLeverCount)) EXPECT_EQ(name, "all");
        const drm::Levers back = drm::parseLevers(name);
        EXPECT_EQ(drm::leversName(back), name);
        EXPECT_EQ(back.topologicalFilter, l.topologicalFilter) << name;
        EXPECT_EQ(back.gapClosing, l.gapClosing) << name;
        EXPECT_EQ(back.confidenceContext, l.confidenceContext) << name;
        EXPECT_EQ(back.angleOrder, l.angleOrder) << name;
        EXPECT_EQ(back.frontNeighbours, l.frontNeighbours) << name;
        EXPECT_EQ(back.boundaryFlag, l.boundaryFlag) << name;
    }
    // The defaults are every lever; a full list names them all.
    EXPECT_EQ(drm::leversName(drm::Levers()), "all");
    EXPECT_EQ(drm::leversName(drm::parseLevers("boundary,front,angle,context,gap,filter")), "all");
}

TEST(Stats, BitsPerVertexAreBytesTimesEightOverVertices) {
    drm::Stats s;
    EXPECT_EQ(s.totalBitsPerVertex(), 0.0);  // no vertices: no division by zero
    s.vertices = 16;
    s.connectivityBytes = 6;
    s.geometryBytes = 20;
    s.totalBytes = 40;
    EXPECT_DOUBLE_EQ(s.connectivityBitsPerVertex(), 3.0);
    EXPECT_DOUBLE_EQ(s.geometryBitsPerVertex(), 10.0);
    EXPECT_DOUBLE_EQ(s.totalBitsPerVertex(), 20.0);
}

TEST(Stats, DescribeRepairsNamesEachRepairWithItsCount) {
    drm::Stats s;
    EXPECT_EQ(drm::describeRepairs(s), "");
    s.splitVertices = 1;
    s.repairBytes = 9;
    EXPECT_EQ(drm::describeRepairs(s), "1 vertex copy (9 bytes)");
    s.splitVertices = 3;
    s.flippedFaces = 2;
    s.repeatedFaces = 1;
    s.looseFaces = 4;
    EXPECT_EQ(drm::describeRepairs(s),
              "3 vertex copies, 2 faces turned over, 1 face repeating another, 4 faces repeating a vertex (9 bytes)");
}

TEST(Version, IsDottedNumbers) {
    const std::string v = drm::version();
    ASSERT_FALSE(v.empty());
    EXPECT_EQ(v.find_first_not_of("0123456789."), std::string::npos) << v;
    EXPECT_EQ(std::count(v.begin(), v.end(), '.'), 2) << v;
}

}  // namespace
