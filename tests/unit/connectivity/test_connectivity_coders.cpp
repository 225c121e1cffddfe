// The table of connectivity coders (connectivity/connectivity_coders.h),
// keyed by the id the header stores: the ids of the ranks and the
// topological coder find their rows under the names the options use,
// nothing else does (Auto is an option, not a coder); the topological
// coder codes the positions itself and never splits in two parts, and the
// header's own test refuses two parts exactly for a coder that does not
// split.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "connectivity/connectivity_coders.h"
#include "container/file_format.h"

namespace drm {
namespace {

TEST(ConnectivityCoders, IdsFindTheirRowsAndNothingElseDoes) {
    for (ConnectivityCoder c : {ConnectivityCoder::Ranks, ConnectivityCoder::Topological}) {
        const ConnectivityCoderEntry* entry = connectivityCoderOf(c);
        ASSERT_NE(entry, nullptr) << int(c);
        EXPECT_EQ(entry->id, c);
        EXPECT_EQ(connectivityCoderById(uint8_t(c)), entry);
        EXPECT_STREQ(entry->name, connectivityCoderName(c));
        EXPECT_EQ(parseConnectivityCoder(entry->name), c);
    }
    EXPECT_EQ(connectivityCoderOf(ConnectivityCoder::Auto), nullptr);
    EXPECT_EQ(connectivityCoderById(0), nullptr);
    for (int id = 3; id < 256; ++id) EXPECT_EQ(connectivityCoderById(uint8_t(id)), nullptr) << id;
}

TEST(ConnectivityCoders, WhatEachCoderDoes) {
    const ConnectivityCoderEntry* ranks = connectivityCoderOf(ConnectivityCoder::Ranks);
    const ConnectivityCoderEntry* topological = connectivityCoderOf(ConnectivityCoder::Topological);
    EXPECT_FALSE(ranks->codesPositions);  // the geometry coder codes them first
    EXPECT_TRUE(ranks->splitsInTwoParts);
    EXPECT_TRUE(topological->codesPositions);
    EXPECT_FALSE(topological->splitsInTwoParts);
    for (const ConnectivityCoderEntry* entry : {ranks, topological}) {
        FileHeader h;
        h.vertexCount = 10;
        h.faceCount = 12;
        h.connectivityCoder = entry->id;
        h.twoParts = true;
        EXPECT_EQ(headerProblem(h).empty(), entry->splitsInTwoParts) << entry->name << ": " << headerProblem(h);
    }
}

}  // namespace
}  // namespace drm
