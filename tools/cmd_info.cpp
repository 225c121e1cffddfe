// drm info IN.drm [--json]: what a .drm file holds.
#include "cli.h"
#include "commands.h"

#include <drm_vcg/file_io.h>

#include <cstdio>
#include <string>

namespace drm {
namespace cli {

const char* const kInfoHelp =
    "usage: drm info IN.drm [--json] [--ranks]\n"
    "\n"
    "Prints IN.drm's counts, options, section sizes and bits per vertex (also\n"
    "of each attribute section: colours, normals, texture coordinates, ...),\n"
    "read from its header and section table without decoding (at once, on\n"
    "any file).\n"
    "\n"
    "options:\n"
    "  --ranks  also decode the file for the boundary edges, the welded\n"
    "           vertices and the histogram of rank codes (rank 0 = boundary\n"
    "           edge); without it those JSON values are null\n"
    "  --json   one JSON object with the keys vertices, faces, components,\n"
    "           boundary_edges, bits, predictor, curvature, connectivity (ranks or\n"
    "           topological), geometry (walk for a topological file, whose\n"
    "           predictor, curvature and levers are null),\n"
    "           refine_bits (low bits of the refine coder, 0 otherwise), levers,\n"
    "           header_bytes, connectivity_bytes, geometry_bytes,\n"
    "           vertex_order_bytes, attribute_bytes, welded_vertices,\n"
    "           attributes (one object per attribute section, in file order:\n"
    "           name, bytes, bpv), total_bytes,\n"
    "           connectivity_bpv, geometry_bpv, attribute_bpv, total_bpv, rank_histogram\n"
    "           (rank -> count, ranks with no codes left out)\n";

namespace {

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        } else {
            out += char(c);
        }
    }
    return out + "\"";
}

std::string leverList(const drm::Levers& levers) {
    std::string out;
    auto add = [&out](bool on, const char* name) {
        if (on) out += (out.empty() ? "" : ", ") + std::string(name);
    };
    add(levers.topologicalFilter, "topological filter");
    add(levers.gapClosing, "gap closing");
    add(levers.confidenceContext, "confidence contexts");
    add(levers.angleOrder, "angle order");
    add(levers.frontNeighbours, "front neighbours");
    add(levers.boundaryFlag, "boundary flags");
    return out.empty() ? "none (the paper's method)" : out;
}

uint64_t totalCodes(const drm::Stats& stats) {
    uint64_t total = 0;
    for (uint64_t count : stats.rankHistogram) total += count;
    return total;
}

double bitsPerVertex(uint64_t bytes, const drm::Stats& s) {
    return s.vertices ? 8.0 * double(bytes) / double(s.vertices) : 0.0;
}

void printJson(const std::string& path, const drm::Stats& s, bool ranks) {
    auto number = [](uint64_t v) { return std::to_string(v); };
    std::string out = "{\n";
    auto field = [&out](const std::string& key, const std::string& value, bool last = false) {
        out += "  " + jsonString(key) + ": " + value + (last ? "\n" : ",\n");
    };
    auto boolean = [](bool b) { return std::string(b ? "true" : "false"); };
    field("file", jsonString(path));
    field("vertices", number(s.vertices));
    field("faces", number(s.faces));
    field("components", number(s.components));
    field("boundary_edges", ranks ? number(s.boundaryEdges) : "null");
    field("bits", std::to_string(s.bits));
    // A topological file's positions are in its walk's order, no vertex
    // coder's; the predictor, curvature and levers are the ranks' alone.
    const bool walk = s.connectivity == drm::ConnectivityCoder::Topological;
    field("predictor", walk ? "null" : jsonString(drm::predictorName(s.predictor)));
    field("curvature", walk ? "null" : boolean(s.curvature));
    field("connectivity", jsonString(drm::connectivityCoderName(s.connectivity)));
    field("geometry", jsonString(walk ? "walk" : drm::geometryCoderName(s.geometry)));
    field("vertex_numbering", jsonString(walk ? "walk" : s.mortonNumbering ? "morton" : "geometry"));
    field("connectivity_parts", std::to_string(s.connectivityParts));
    field("refine_bits", std::to_string(s.refineBits));
    field("levers", walk ? std::string("null") : "{\"topological_filter\": " + boolean(s.levers.topologicalFilter) +
                        ", \"gap_closing\": " + boolean(s.levers.gapClosing) +
                        ", \"confidence_context\": " + boolean(s.levers.confidenceContext) +
                        ", \"angle_order\": " + boolean(s.levers.angleOrder) +
                        ", \"front_neighbours\": " + boolean(s.levers.frontNeighbours) +
                        ", \"boundary_flag\": " + boolean(s.levers.boundaryFlag) + "}");
    field("header_bytes", number(s.headerBytes));
    field("connectivity_bytes", number(s.connectivityBytes));
    field("geometry_bytes", number(s.geometryBytes));
    field("vertex_order_bytes", number(s.vertexOrderBytes));
    field("attribute_bytes", number(s.attributeBytes));
    field("welded_vertices", ranks ? number(s.weldedVertices) : "null");
    std::string sections = "[";
    for (const drm::Stats::AttributeSize& section : s.attributeSizes)
        sections += std::string(sections.size() > 1 ? ", " : "") + "{\"name\": " + jsonString(section.name) +
                    ", \"bytes\": " + number(section.bytes) + ", \"bpv\": " + fixed(bitsPerVertex(section.bytes, s), 6) +
                    "}";
    field("attributes", sections + "]");
    field("total_bytes", number(s.totalBytes));
    field("connectivity_bpv", fixed(s.connectivityBitsPerVertex(), 6));
    field("geometry_bpv", fixed(s.geometryBitsPerVertex(), 6));
    field("attribute_bpv", fixed(bitsPerVertex(s.attributeBytes, s), 6));
    field("total_bpv", fixed(s.totalBitsPerVertex(), 6));
    std::string histogram = "{";
    for (size_t rank = 0; rank < s.rankHistogram.size(); ++rank) {
        if (s.rankHistogram[rank] == 0) continue;
        histogram += (histogram.size() > 1 ? ", " : "") + jsonString(std::to_string(rank)) + ": " +
                     number(s.rankHistogram[rank]);
    }
    field("rank_histogram", ranks ? histogram + "}" : "null", true);
    out += "}\n";
    std::fputs(out.c_str(), stdout);
}

void printText(const std::string& path, const drm::Stats& s, bool ranks) {
    auto row = [](const char* key, const std::string& value) { std::printf("%-20s %s\n", key, value.c_str()); };
    auto bytesAndRate = [](uint64_t bytes, double bpv) {
        return std::to_string(bytes) + " (" + fixed(bpv, 3) + " bits per vertex)";
    };
    row("file", path);
    row("vertices", std::to_string(s.vertices));
    row("faces", std::to_string(s.faces));
    row("components", std::to_string(s.components));
    if (ranks) row("boundary edges", std::to_string(s.boundaryEdges));
    row("bits per axis", std::to_string(s.bits));
    // The predictor, curvature and levers are the distance ranks' alone.
    const bool walk = s.connectivity == drm::ConnectivityCoder::Topological;
    if (!walk) {
        row("predictor", drm::predictorName(s.predictor));
        row("curvature", s.curvature ? "on" : "off");
    }
    row("connectivity coder", walk ? "topological (positions in the order met; no distance ranks)" : "distance ranks");
    if (walk) row("geometry coder", "positions in the walk's order (topological)");
    else row("geometry coder", s.refineBits > 0 ? std::string(drm::geometryCoderName(s.geometry)) + " (" +
                                                  std::to_string(s.refineBits) + " low bits)"
                                            : std::string(drm::geometryCoderName(s.geometry)));
    row("vertex numbering", walk ? "the order the topological walk meets them"
                            : s.mortonNumbering                                     ? "Morton order"
                                                                                    : "the geometry coder's order");
    if (s.connectivityParts > 1) row("connectivity parts", std::to_string(s.connectivityParts) + " (decoded side by side)");
    if (!walk) row("levers", leverList(s.levers));
    row("header bytes", std::to_string(s.headerBytes));
    row("connectivity bytes", bytesAndRate(s.connectivityBytes, s.connectivityBitsPerVertex()));
    row("geometry bytes", bytesAndRate(s.geometryBytes, s.geometryBitsPerVertex()));
    if (s.vertexOrderBytes > 0) row("vertex order bytes", std::to_string(s.vertexOrderBytes));
    if (!s.attributeSizes.empty()) {
        row("attribute bytes", bytesAndRate(s.attributeBytes, bitsPerVertex(s.attributeBytes, s)));
        uint64_t listed = 0;
        for (const drm::Stats::AttributeSize& section : s.attributeSizes) {
            std::printf("  %-18s %s\n", section.name.c_str(),
                        bytesAndRate(section.bytes, bitsPerVertex(section.bytes, s)).c_str());
            listed += section.bytes;
        }
        // Section lengths and kinds, in no section's payload: listed so the
        // lines add up to the attribute bytes.
        if (s.attributeBytes > listed)
            std::printf("  %-18s %s\n", "framing",
                        bytesAndRate(s.attributeBytes - listed, bitsPerVertex(s.attributeBytes - listed, s)).c_str());
    }
    if (ranks && s.weldedVertices > 0) row("welded vertices", std::to_string(s.weldedVertices));
    row("total bytes", bytesAndRate(s.totalBytes, s.totalBitsPerVertex()));
    if (walk) {
        std::printf("rank codes           none (a topological file)\n");
        return;
    }
    if (!ranks) {
        std::printf("rank codes           (drm info --ranks decodes the file to count them)\n");
        return;
    }
    const uint64_t codes = totalCodes(s);
    std::printf("rank codes           %llu (rank: count, share)\n", (unsigned long long)codes);
    for (size_t rank = 0; rank < s.rankHistogram.size(); ++rank) {
        if (s.rankHistogram[rank] == 0) continue;
        std::printf("  %6zu %10llu %7s%%%s\n", rank, (unsigned long long)s.rankHistogram[rank],
                    fixed(codes ? 100.0 * double(s.rankHistogram[rank]) / double(codes) : 0.0, 2).c_str(),
                    rank == 0 ? "  (boundary edges)" : "");
    }
}

}  // namespace

int runInfo(const std::vector<std::string>& args) {
    const Arguments parsed = parseArguments("info", args, {}, {"--json", "--ranks"});
    parsed.expectPositional(1, 1, "one .drm file");
    const std::string& input = parsed.positional[0];
    const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(input);
    // The header and section table say everything but the ranks (and a
    // welded mesh's decoded vertex count): read at once, whatever the
    // file's size. Only --ranks decodes.
    drm::Stats stats;
    try {
        stats = drm::inspect(bytes).stats;
    } catch (const drm::Error& e) {
        throw drm::Error(e.kind(), "cannot decode " + input + ": " + e.what());
    }
    const bool ranks = parsed.has("--ranks");
    if (ranks) {
        ProgressBar bar("reading " + fileName(input));
        try {
            stats = drm::decode(bytes, bar.callback()).stats;
        } catch (const drm::Error& e) {
            throw drm::Error(e.kind(), "cannot decode " + input + ": " + e.what());
        }
    }
    if (parsed.has("--json")) printJson(input, stats, ranks);
    else printText(input, stats, ranks);
    return 0;
}

}  // namespace cli
}  // namespace drm
