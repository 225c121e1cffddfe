// The colours of distance ranks: one palette for `drm ranks` and the MeshLab
// rank filter, so a picture means the same thing in both. The only place the
// colours are written: the filter's help and log legend are made from it, and
// tests hold README.md's legend to it.
//
// Faces are coloured by the rank code that created them (drm::Encoded::
// faceRank), bucketed as in the paper's Figure 1: the common rank 1 is
// quiet, rarer ranks are ever louder. Bucket 0 is a component's start
// triangle, which is stored, not ranked. C++14-clean, no dependencies.
#ifndef DRM_VCG_RANK_PALETTE_H
#define DRM_VCG_RANK_PALETTE_H

#include <cstdint>
#include <string>

namespace drm {
namespace vcgio {

struct RankColour {
    uint8_t r, g, b;
};

const int kRankBucketCount = 5;  // start triangle, 1, 2, 3, 4+

inline int rankBucket(uint32_t rank) { return rank >= 4 ? 4 : int(rank); }

inline RankColour rankBucketColour(int bucket) {
    static const RankColour colours[kRankBucketCount] = {
        {64, 64, 64},     // start triangle: dark grey
        {180, 192, 206},  // rank 1: pale blue-grey
        {76, 175, 80},    // rank 2: green
        {245, 166, 35},   // rank 3: orange
        {214, 39, 40},    // rank 4 and above: red
    };
    return colours[bucket < 0 ? 0 : (bucket >= kRankBucketCount ? kRankBucketCount - 1 : bucket)];
}

// Legend text of a bucket.
inline const char* rankBucketName(int bucket) {
    static const char* const names[kRankBucketCount] = {"start triangle", "rank 1", "rank 2", "rank 3",
                                                        "rank 4+"};
    return names[bucket < 0 ? 0 : (bucket >= kRankBucketCount ? kRankBucketCount - 1 : bucket)];
}

// The colour's name in words ("pale blue-grey"), for legends and help.
inline const char* rankBucketColourName(int bucket) {
    static const char* const names[kRankBucketCount] = {"dark grey", "pale blue-grey", "green", "orange", "red"};
    return names[bucket < 0 ? 0 : (bucket >= kRankBucketCount ? kRankBucketCount - 1 : bucket)];
}

// "#b4c0ce": the colour as HTML and the docs write it.
inline std::string rankBucketHex(int bucket) {
    static const char digits[] = "0123456789abcdef";
    const RankColour c = rankBucketColour(bucket);
    const uint8_t parts[3] = {c.r, c.g, c.b};
    std::string hex = "#";
    for (uint8_t v : parts) {
        hex += digits[v >> 4];
        hex += digits[v & 15];
    }
    return hex;
}

inline RankColour rankColour(uint32_t rank) { return rankBucketColour(rankBucket(rank)); }

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_RANK_PALETTE_H
