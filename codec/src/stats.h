// Stats, filled the same way wherever a file's figures are known: by the
// encoder from the file it has just written, by the decoder and inspect()
// from the file they read. One builder, so the three cannot disagree on
// what a field means.
#ifndef DRM_STATS_H
#define DRM_STATS_H

#include <cstddef>

#include "drmcodec/drmcodec.h"
#include "container/file_format.h"
#include "mesh/repair_section.h"

namespace drm {

// The figures the header and section table give (counts, options, section
// sizes, total). Those that need a payload coded or decoded (ranks, refine
// bits, repairs' face counts, attribute names, a welded mesh's vertex
// count) are left alone.
void fillStatsFromHeader(Stats& stats, const FileParts& parts, size_t fileSize);

// The figures only the traversal tells, for the encoder and the decoder:
// boundary edges (the rank-0 codes of stats.rankHistogram, which the caller
// has filled), the low bits of a two-pass geometry coder, and the faces the
// repairs turned over, repeated or kept whole (repairs empty for a mesh
// that needed none).
void fillStatsFromTraversal(Stats& stats, int refineBits, const Repairs& repairs);

}  // namespace drm

#endif  // DRM_STATS_H
