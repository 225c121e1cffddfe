// What the plugins write in MeshLab's log, as text (meshlabserver's stdout)
// or HTML (the GUI's log pane). No MeshLab or Qt types: tested on its own.
//
// The GUI's log pane is a QPlainTextEdit: it takes HTML, but lays out no
// tables and collapses runs of spaces, so the legend is one line per colour,
// a swatch followed by columns padded with non-breaking spaces in the
// pane's monospace font.
#ifndef DRM_MESHLAB_LOG_TEXT_H
#define DRM_MESHLAB_LOG_TEXT_H

#include <drmcodec/drmcodec.h>

#include <cstdint>
#include <string>
#include <vector>

namespace drm_meshlab {

// The file's size and where it goes, parts adding up to the total:
// "10877 bytes, 13.44 bpv = header 31 B (0.04) + connectivity 526 B (0.65)
// + geometry 10320 B (12.75)", then vertex order, repairs and attributes
// when the file has them (attributes by name, as drm::Stats lists them).
std::string sizeBreakdown(const drm::Stats& stats);

// The parts sizeBreakdown lists, in its order: name and byte count.
struct SizePart {
    std::string name;
    uint64_t bytes;
};
std::vector<SizePart> sizeParts(const drm::Stats& stats);

// The filter's help text: what it does, with the palette's colours as
// coloured words (made from drm_vcg/rank_palette.h).
std::string rankFilterHelpHtml();

// The legend of the rank colours with the faces of each, for the GUI's log:
// a heading, then per colour a swatch, its meaning, face count and share.
std::string rankLegendHtml(const std::vector<uint64_t>& facesPerBucket);

// The same as plain lines ("  rank 1          #b4c0ce      12345   95.10%"),
// for meshlabserver's stdout and -l log.
std::vector<std::string> rankLegendText(const std::vector<uint64_t>& facesPerBucket);

// "Rank codes (0 = boundary edge): 0:12 1:3456 ..." (the first twelve codes,
// the rest summed).
std::string rankHistogramText(const drm::Stats& stats);

// Escapes &, < and > for HTML.
std::string escapeHtml(const std::string& text);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_LOG_TEXT_H
