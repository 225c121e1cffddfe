// The colours of distance ranks, as the `drm` tool and the MeshLab rank
// filter use them, so a picture means the same thing in both. The palette
// itself is written once, in the codec (drm::rankPaletteEntry, drm.h):
// these are its adapters for the tools and the plugins (colour structs,
// hex for HTML and the docs); the filter's help and log legend are made
// from them, and tests hold README.md's legend to them.
//
// Faces are coloured by the rank code that created them (drm::Encoded::
// faceRank), bucketed as in the paper's Figure 1: the common rank 1 is
// quiet, rarer ranks are ever louder. Bucket 0 is a component's start
// triangle, which is stored, not ranked. C++14-clean.
#ifndef DRM_VCG_RANK_PALETTE_H
#define DRM_VCG_RANK_PALETTE_H

#include <cstdint>
#include <string>

#include <drm/drm.h>

namespace drm {
namespace vcgio {

struct RankColour {
    uint8_t r, g, b;
};

const int kRankBucketCount = drm::kRankBucketCount;  // start triangle, 1, 2, 3, 4+

inline int rankBucket(uint32_t rank) { return drm::rankBucket(rank); }

// Buckets out of range are clamped, as drm::rankPaletteEntry does.
inline RankColour rankBucketColour(int bucket) {
    const drm::RankPaletteEntry& e = drm::rankPaletteEntry(bucket);
    return {e.r, e.g, e.b};
}

// Legend text of a bucket ("rank 1").
inline const char* rankBucketName(int bucket) { return drm::rankPaletteEntry(bucket).label; }

// The colour's name in words ("pale blue-grey"), for legends and help.
inline const char* rankBucketColourName(int bucket) { return drm::rankPaletteEntry(bucket).colourName; }

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
