#include "bridge/log_text.h"

#include "bridge/encoding.h"

#include <drm_vcg/rank_palette.h>

#include <algorithm>
#include <cstdio>

namespace drm_meshlab {

namespace {

double bitsPerVertex(uint64_t bytes, uint64_t vertices) {
    return vertices == 0 ? 0.0 : 8.0 * double(bytes) / double(vertices);
}

std::string percent(uint64_t n, uint64_t total) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.2f%%", total ? 100.0 * double(n) / double(total) : 0.0);
    return text;
}

// TEXT padded to WIDTH characters, on the left (right-aligned) or the
// right, its spaces and the padding non-breaking: the pane neither collapses
// nor breaks them.
std::string padded(const std::string& text, size_t width, bool alignRight) {
    std::string pad;
    for (size_t i = text.size(); i < width; ++i) pad += "&nbsp;";
    std::string kept;
    for (char c : escapeHtml(text)) kept += c == ' ' ? std::string("&nbsp;") : std::string(1, c);
    return alignRight ? pad + kept : kept + pad;
}

}  // namespace

std::string escapeHtml(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else out += c;
    }
    return out;
}

std::vector<SizePart> sizeParts(const drm::Stats& stats) {
    std::vector<SizePart> parts = {{"header", stats.headerBytes},
                                   {"connectivity", stats.connectivityBytes},
                                   {"geometry", stats.geometryBytes}};
    if (stats.vertexOrderBytes > 0) parts.push_back({"vertex order", stats.vertexOrderBytes});
    if (stats.repairBytes > 0) parts.push_back({"repairs", stats.repairBytes});
    if (stats.attributeBytes > 0) {
        // Each section by name; framing bytes not in any payload listed last.
        uint64_t named = 0;
        for (const drm::Stats::AttributeSize& a : stats.attributeSizes) {
            parts.push_back({a.name.empty() ? std::string("attributes") : a.name, a.bytes});
            named += a.bytes;
        }
        if (stats.attributeBytes > named) parts.push_back({"attribute framing", stats.attributeBytes - named});
    }
    return parts;
}

std::string sizeBreakdown(const drm::Stats& stats) {
    std::string text = std::to_string(stats.totalBytes) + " bytes, " + twoDecimals(stats.totalBitsPerVertex()) +
                       " bpv =";
    bool first = true;
    for (const SizePart& part : sizeParts(stats)) {
        text += (first ? " " : " + ") + part.name + " " + std::to_string(part.bytes) + " B (" +
                twoDecimals(bitsPerVertex(part.bytes, stats.vertices)) + ")";
        first = false;
    }
    return text;
}

std::string rankFilterHelpHtml() {
    using namespace drm::vcgio;
    // A swatch of the colour before its name: the name written in its own
    // colour is unreadable for the pale ones on the dialog's grey.
    auto coloured = [](int bucket) {
        return "<span style='background-color:" + rankBucketHex(bucket) + "; color:" + rankBucketHex(bucket) +
               "'>&nbsp;&nbsp;&nbsp;</span>&nbsp;<b>" + rankBucketColourName(bucket) + "</b>";
    };
    return "Compresses the mesh's connectivity with distance-ranked coding (the .drm format) and colours "
           "every face by the rank code that created it: " +
           coloured(0) + " for a component's start triangle, " + coloured(1) +
           " for rank 1 (the nearest candidate closed the triangle: almost free), " + coloured(2) + " for 2, " +
           coloured(3) + " for 3 and " + coloured(4) +
           " for 4 and above. The rank is also stored as face quality. The log shows this legend with the "
           "faces of each colour, the connectivity cost in bits per vertex and the rank histogram. Any "
           "triangle mesh works: non-manifold parts are cut apart for the traversal (the log says what it "
           "cost). The mesh is not changed otherwise.<br>"
           "Same colours as the <tt>drm ranks</tt> command.<br><br>"
           "See: <br><i>P. Marais, J. Gain, D. Shreiner</i><br>"
           "<b>\"Distance-Ranked Connectivity Compression of Triangle Meshes\"</b><br>"
           "Computer Graphics Forum, 2007 (Figure 1).";
}

std::string rankLegendHtml(const std::vector<uint64_t>& facesPerBucket) {
    using namespace drm::vcgio;
    uint64_t faces = 0;
    for (uint64_t n : facesPerBucket) faces += n;
    // About 40 characters a line: the log pane beside the 3D view is narrow.
    std::string html = "<b>Faces per colour</b> (" + std::to_string(faces) + " faces):";
    for (int bucket = 0; bucket < kRankBucketCount && size_t(bucket) < facesPerBucket.size(); ++bucket) {
        const uint64_t n = facesPerBucket[size_t(bucket)];
        const std::string hex = rankBucketHex(bucket);
        html += "<br><span style='background-color:" + hex + "; color:" + hex +
                "'>&nbsp;&nbsp;&nbsp;&nbsp;</span>&nbsp;" + padded(rankBucketName(bucket), 15, false) +
                padded(std::to_string(n), 9, true) + padded(percent(n, faces), 9, true);
    }
    return html;
}

std::vector<std::string> rankLegendText(const std::vector<uint64_t>& facesPerBucket) {
    using namespace drm::vcgio;
    std::vector<std::string> lines;
    uint64_t faces = 0;
    for (uint64_t n : facesPerBucket) faces += n;
    lines.push_back("Faces per colour:");
    for (int bucket = 0; bucket < kRankBucketCount && size_t(bucket) < facesPerBucket.size(); ++bucket) {
        const uint64_t n = facesPerBucket[size_t(bucket)];
        char line[160];
        std::snprintf(line, sizeof(line), "  %-15s %s %10llu  %7s", rankBucketName(bucket),
                      rankBucketHex(bucket).c_str(), (unsigned long long)n, percent(n, faces).c_str());
        lines.push_back(line);
    }
    return lines;
}

std::string rankHistogramText(const drm::Stats& stats) {
    // Rank 0 marks a boundary edge, which creates no face, so these counts
    // differ from the faces per colour.
    std::string histogram = "Rank codes (0 = boundary edge):";
    const size_t shown = 12;  // the tail of a long histogram is summed
    uint64_t tail = 0;
    size_t tailFrom = 0;
    for (size_t r = 0; r < stats.rankHistogram.size(); ++r) {
        const uint64_t n = stats.rankHistogram[r];
        if (r < shown) {
            if (n > 0) histogram += " " + std::to_string(r) + ":" + std::to_string(n);
        } else {
            if (tail == 0 && n > 0) tailFrom = r;
            tail += n;
        }
    }
    if (tail > 0)
        histogram += " " + std::to_string(tailFrom) + "-" + std::to_string(stats.rankHistogram.size() - 1) + ":" +
                     std::to_string(tail);
    return histogram;
}

}  // namespace drm_meshlab
