// The colours of distance ranks, written once here and used by the `drm`
// tool (`drm ranks`, `drm render --by-rank`) and the MeshLab rank filter,
// so a picture means the same thing in both: colour structs, names, hex
// for HTML and the docs. The filter's help and log legend are made from
// them, and tests hold the docs' legend to them.
//
// Faces are coloured by the rank code that created them (drm::Encoded::
// faceRank), bucketed as in the paper's Figure 1: the common rank 1 is
// quiet, rarer ranks are ever louder. Bucket 0 is a component's start
// triangle, which is stored, not ranked. C++14-clean.
#ifndef DRM_VCG_RANK_PALETTE_H
#define DRM_VCG_RANK_PALETTE_H

#include <cstdint>
#include <string>

#include <drmcodec/drmcodec.h>

namespace drm {
namespace vcgio {

struct RankColour {
    uint8_t r, g, b;
};

const int kRankBucketCount = 5;  // start triangle, ranks 1, 2, 3, 4 and above

inline int rankBucket(uint32_t rank) { return rank >= 4 ? 4 : int(rank); }

struct RankPaletteEntry {
    uint8_t r, g, b;
    const char* colourName;  // "pale blue-grey"
    const char* label;       // "rank 1"
};

// Buckets out of range are clamped to 0 .. kRankBucketCount - 1.
inline const RankPaletteEntry& rankPaletteEntry(int bucket) {
    static const RankPaletteEntry palette[kRankBucketCount] = {
        {64, 64, 64, "dark grey", "start triangle"},
        {180, 192, 206, "pale blue-grey", "rank 1"},
        {76, 175, 80, "green", "rank 2"},
        {245, 166, 35, "orange", "rank 3"},
        {214, 39, 40, "red", "rank 4+"},
    };
    return palette[bucket < 0 ? 0 : (bucket >= kRankBucketCount ? kRankBucketCount - 1 : bucket)];
}

inline RankColour rankBucketColour(int bucket) {
    const RankPaletteEntry& e = rankPaletteEntry(bucket);
    return {e.r, e.g, e.b};
}

// Legend text of a bucket ("rank 1").
inline const char* rankBucketName(int bucket) { return rankPaletteEntry(bucket).label; }

// The colour's name in words ("pale blue-grey"), for legends and help.
inline const char* rankBucketColourName(int bucket) { return rankPaletteEntry(bucket).colourName; }

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
