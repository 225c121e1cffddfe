#include "report.h"

#include "table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

namespace drm {
namespace peers {
namespace {

// drm's figures are divided by the reference's: Draco at its strongest level,
// the usual baseline for mesh compression.
const char* const kSubjects[] = {"drm", "drm paper"};
const char* const kReference = "draco cl10";

int codecIndex(const BenchRun& run, const std::string& name) {
    const auto found = std::find(run.codecs.begin(), run.codecs.end(), name);
    return found == run.codecs.end() ? -1 : int(found - run.codecs.begin());
}

bool isSubject(const std::string& name) {
    return std::find(std::begin(kSubjects), std::end(kSubjects), name) != std::end(kSubjects);
}

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

enum class Metric { Connectivity, Total, Encode, Decode };

const char* metricTitle(Metric metric) {
    switch (metric) {
    case Metric::Connectivity: return "Connectivity, bits per vertex";
    case Metric::Total: return "Whole file, bits per vertex";
    case Metric::Encode: return "Encode time, milliseconds";
    case Metric::Decode: return "Decode time, milliseconds";
    }
    return "";
}

double valueOf(const MeshResult& mesh, const Measurement& codec, Metric metric) {
    switch (metric) {
    case Metric::Connectivity: return 8.0 * double(codec.connectivityBytes) / double(mesh.vertices);
    case Metric::Total: return 8.0 * double(codec.totalBytes) / double(mesh.vertices);
    case Metric::Encode: return 1000 * codec.encodeSeconds;
    case Metric::Decode: return 1000 * codec.decodeSeconds;
    }
    return 0;
}

std::string format(double value, Metric metric) {
    if (metric == Metric::Connectivity || metric == Metric::Total) return fixed(value, 3);
    return fixed(value, value < 1 ? 3 : value < 100 ? 2 : 1);  // milliseconds
}

bool lostOrAddedFaces(const MeshResult& mesh, const Measurement& codec) {
    return codec.measured && codec.decoded.triangles != mesh.triangles;
}

// drm's (or the paper method's) figure over a peer's, on every mesh where
// both were measured.
struct Ratios {
    std::vector<double> values;
    size_t subjectSmaller = 0;  // meshes where drm's figure is the smaller

    double geometricMean() const {
        double logSum = 0;
        for (double v : values) logSum += std::log(v);
        return values.empty() ? 0 : std::exp(logSum / double(values.size()));
    }
    std::string range() const {
        if (values.empty()) return "-";
        const auto bounds = std::minmax_element(values.begin(), values.end());
        return fixed(*bounds.first, 2) + " - " + fixed(*bounds.second, 2);
    }
};

Ratios ratiosOf(const BenchRun& run, int subject, int peer, Metric metric) {
    Ratios ratios;
    for (const MeshResult& mesh : run.meshes) {
        if (!mesh.read || !mesh.codecs[subject].measured || !mesh.codecs[peer].measured) continue;
        const double mine = valueOf(mesh, mesh.codecs[subject], metric);
        const double theirs = valueOf(mesh, mesh.codecs[peer], metric);
        if (mine < theirs) ++ratios.subjectSmaller;
        // A zero would sink the geometric mean; no codec writes zero bytes
        // for a mesh, and timers do not read zero, so this only guards.
        if (mine > 0 && theirs > 0) ratios.values.push_back(mine / theirs);
    }
    return ratios;
}

// One row per mesh, one column per codec, then drm / draco cl10.
Table perMeshTable(const BenchRun& run, Metric metric) {
    const int subject = codecIndex(run, kSubjects[0]);
    const int reference = codecIndex(run, kReference);
    const bool sizes = metric == Metric::Connectivity;
    Table table;
    table.addColumn("mesh", false);
    if (sizes) {
        table.addColumn("V", true);
        table.addColumn("T", true);
        table.addColumn("paper DR", true);
    }
    for (const std::string& codec : run.codecs) table.addColumn(codec, true);
    const bool withRatio = subject >= 0 && reference >= 0;
    if (withRatio) table.addColumn(std::string(kSubjects[0]) + " / " + kReference, true);

    for (const MeshResult& mesh : run.meshes) {
        std::vector<std::string> row{mesh.name};
        if (sizes) {
            row.push_back(mesh.read ? std::to_string(mesh.vertices) : "-");
            row.push_back(mesh.read ? std::to_string(mesh.triangles) : "-");
            row.push_back(mesh.hasPaper ? fixed(mesh.paperBpv, 2) : "-");
        }
        for (size_t c = 0; c < run.codecs.size(); ++c) {
            if (!mesh.read || !mesh.codecs[c].measured) {
                row.push_back("-");
                continue;
            }
            // '*': the decoder gave back another triangle count (see the notes).
            row.push_back(format(valueOf(mesh, mesh.codecs[c], metric), metric) +
                          (lostOrAddedFaces(mesh, mesh.codecs[c]) ? "*" : ""));
        }
        if (withRatio) {
            const bool both = mesh.read && mesh.codecs[subject].measured && mesh.codecs[reference].measured;
            const double theirs = both ? valueOf(mesh, mesh.codecs[reference], metric) : 0;
            row.push_back(theirs > 0 ? fixed(valueOf(mesh, mesh.codecs[subject], metric) / theirs, 2) : "-");
        }
        table.rows.push_back(row);
    }
    return table;
}

// drm and the paper's method against every peer: geometric means of the
// per-mesh ratios (below 1: drm smaller or faster).
Table summaryTable(const BenchRun& run) {
    Table table;
    table.addColumn("ratio", false);
    table.addColumn("meshes", true);
    table.addColumn("conn smaller", true);
    table.addColumn("conn", true);
    table.addColumn("conn range", true);
    table.addColumn("total", true);
    table.addColumn("total range", true);
    table.addColumn("encode time", true);
    table.addColumn("decode time", true);
    for (const char* subjectName : kSubjects) {
        const int subject = codecIndex(run, subjectName);
        if (subject < 0) continue;
        for (size_t peer = 0; peer < run.codecs.size(); ++peer) {
            if (isSubject(run.codecs[peer])) continue;
            const Ratios connectivity = ratiosOf(run, subject, int(peer), Metric::Connectivity);
            const Ratios total = ratiosOf(run, subject, int(peer), Metric::Total);
            const Ratios encode = ratiosOf(run, subject, int(peer), Metric::Encode);
            const Ratios decode = ratiosOf(run, subject, int(peer), Metric::Decode);
            table.rows.push_back({std::string(subjectName) + " / " + run.codecs[peer],
                                  std::to_string(connectivity.values.size()),
                                  std::to_string(connectivity.subjectSmaller),
                                  fixed(connectivity.geometricMean(), 2), connectivity.range(),
                                  fixed(total.geometricMean(), 2), total.range(),
                                  fixed(encode.geometricMean(), 2), fixed(decode.geometricMean(), 2)});
        }
    }
    return table;
}

std::string shortened(const std::string& text, size_t limit) {
    return text.size() <= limit ? text : text.substr(0, limit - 3) + "...";
}

// Refusals, failures, and decoded counts that differ from the input.
std::vector<std::string> notesOf(const BenchRun& run) {
    std::vector<std::string> notes;
    for (const MeshResult& mesh : run.meshes) {
        if (!mesh.read) {
            notes.push_back(mesh.name + ": not read: " + mesh.readError);
            continue;
        }
        for (size_t c = 0; c < run.codecs.size(); ++c) {
            const Measurement& codec = mesh.codecs[c];
            const std::string who = mesh.name + ", " + run.codecs[c] + ": ";
            if (!codec.measured) {
                notes.push_back(who + (isSubject(run.codecs[c]) ? "refused: " : "failed: ") + shortened(codec.error, 160));
                continue;
            }
            if (codec.decoded.triangles != mesh.triangles)
                notes.push_back(who + "decoded " + std::to_string(codec.decoded.triangles) + " of " +
                                std::to_string(mesh.triangles) + " triangles");
            if (codec.decoded.vertices != mesh.vertices)
                notes.push_back(who + "decoded " + std::to_string(codec.decoded.vertices) + " of " +
                                std::to_string(mesh.vertices) + " vertices");
        }
    }
    return notes;
}

std::string cpuName() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.compare(0, 10, "model name") == 0) {
            const size_t colon = line.find(':');
            if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
        }
    }
    return "unknown CPU";
}

std::string today() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
    return text;
}

const Metric kMetrics[] = {Metric::Connectivity, Metric::Total, Metric::Encode, Metric::Decode};

// The headline sentence: drm against Draco's connectivity alone, over the
// meshes drm encodes.
std::string headline(const BenchRun& run) {
    const int subject = codecIndex(run, kSubjects[0]);
    const int reference = codecIndex(run, kReference);
    if (subject < 0 || reference < 0) return "";
    size_t encoded = 0;
    for (const MeshResult& mesh : run.meshes) encoded += mesh.read && mesh.codecs[subject].measured;
    const Ratios connectivity = ratiosOf(run, subject, reference, Metric::Connectivity);
    const Ratios total = ratiosOf(run, subject, reference, Metric::Total);
    const Ratios encode = ratiosOf(run, subject, reference, Metric::Encode);
    const Ratios decode = ratiosOf(run, subject, reference, Metric::Decode);
    std::ostringstream out;
    if (encoded == run.meshes.size())
        out << "drm encodes all " << encoded << " meshes.";
    else
        out << "drm encodes " << encoded << " of the " << run.meshes.size() << " meshes (the notes say why not "
            << "the others; the peers' figures for those are still in the tables).";
    out << " On the meshes drm encodes, its connectivity is "
        << "smaller than Draco's connectivity alone (cl10) on " << connectivity.subjectSmaller << " of "
        << connectivity.values.size() << " meshes, " << fixed(connectivity.geometricMean(), 2)
        << " times Draco's in geometric mean (" << connectivity.range() << "). drm's whole file is "
        << fixed(total.geometricMean(), 2) << " times Draco cl10's (" << total.range() << "); drm takes "
        << fixed(encode.geometricMean(), 1) << " times Draco cl10's time to encode and "
        << fixed(decode.geometricMean(), 1) << " times to decode (geometric means of per-mesh ratios).";
    // Where drm loses, largest ratio first: the meshes to look at.
    std::vector<std::pair<double, std::string>> larger;
    for (const MeshResult& mesh : run.meshes) {
        if (!mesh.read || !mesh.codecs[subject].measured || !mesh.codecs[reference].measured) continue;
        const double ratio = valueOf(mesh, mesh.codecs[subject], Metric::Connectivity) /
                             valueOf(mesh, mesh.codecs[reference], Metric::Connectivity);
        if (ratio >= 1) larger.emplace_back(ratio, mesh.name);
    }
    std::sort(larger.rbegin(), larger.rend());
    if (!larger.empty()) {
        out << " drm's connectivity is not smaller on";
        for (size_t i = 0; i < larger.size(); ++i)
            out << (i ? ", " : " ") << larger[i].second << " (" << fixed(larger[i].first, 2) << ")";
        out << ".";
    }
    return out.str();
}

}  // namespace

std::string textReport(const BenchRun& run) {
    std::ostringstream out;
    for (Metric metric : kMetrics) {
        out << metricTitle(metric) << (metric == Metric::Encode || metric == Metric::Decode
                                           ? " (best of " + std::to_string(run.runs) + ")"
                                           : std::string())
            << "\n" << toText(perMeshTable(run, metric)) << "\n";
    }
    out << "drm's figure over each peer's (geometric mean of per-mesh ratios; below 1: drm smaller or faster)\n"
        << toText(summaryTable(run)) << "\n";
    const std::string line = headline(run);
    if (!line.empty()) out << line << "\n\n";
    const std::vector<std::string> notes = notesOf(run);
    if (!notes.empty()) out << "notes\n";
    for (const std::string& note : notes) out << "  " << note << "\n";
    return out.str();
}

std::string markdownReport(const BenchRun& run) {
    std::ostringstream out;
    out << "# drm against other mesh codecs\n\n"
        << "Generated by `drm-peer-bench` (`tools/bench/`); regenerate rather than edit:\n\n"
        << "```sh\n"
        << "bash scripts/setup.sh      # installs libdraco-dev, libmeshoptimizer-dev, libopenctm-dev, libzstd-dev too\n"
        << "cmake -S . -B build -G Ninja && cmake --build build --target drm-peer-bench\n"
        << run.command << "\n"
        << "```\n\n"
        << "Every codec gets the same indexed triangles, read from each file of the folder by drm's reader, and "
        << "quantizes positions to the same " << run.bits << "-bit grid: one cubic step over the bounding box "
        << "(largest extent / (2^" << run.bits << " - 1)). Bits per vertex (bpv) always divide by the input's vertex "
        << "count. Times are `std::chrono::steady_clock` around the codec calls only (converting the mesh to the "
        << "codec's own input type is not timed), best of " << run.runs << " runs each, all in one process on "
        << cpuName() << " (" << std::thread::hardware_concurrency() << " cores shared with other work), "
        << today() << ". Absolute times move from run to run on such a machine; the ratios, taken within one "
        << "run, are the figures to compare.\n\n"
        << "Codecs:\n\n";
    for (size_t c = 0; c < run.codecs.size(); ++c)
        out << "- **" << run.codecs[c] << "**: " << run.descriptions[c] << ".\n";
    out << "\n"
        << "How connectivity is counted. drm: the connectivity section, the rank stream as the paper counts it "
        << "and the start triangles of the components (the header not included); in a file of "
        << "the topological coder, its symbols (the positions are in the geometry section). Draco: the real cl10/cl7 file is written by a subclass of "
        << "`draco::MeshEdgebreakerEncoder` that records the buffer size before and after the connectivity "
        << "stage (`EncodeConnectivity`, a protected virtual of Draco's public headers); the file is checked to be "
        << "byte-identical to `draco::Encoder`'s, and the stage holds the Edgebreaker symbols, split and hole data "
        << "and a few bytes of vertex and face counts. Levels 10 and 7 code connectivity the same way (valence "
        << "Edgebreaker, or standard Edgebreaker below 1000 faces) and differ in how positions are predicted. "
        << "Cross-check, made once with Draco 1.5.5 while writing this tool: encoding a mesh with every position "
        << "set equal (one position value per point, so nothing is merged) keeps every face and gives the same "
        << "stage size on bunny, fandisk, horse, torus and dragon-res3, plus 80 to 153 bytes of header, attribute "
        << "descriptors and an all-zero position stream; through `draco_encoder`, whose reader merges equal "
        << "positions, the same trick fails (\"All triangles are degenerate\"). "
        << "meshoptimizer: the zstd-compressed index codec output. OpenCTM: the `INDX` chunk of the MG2 file.\n\n"
        << "## Summary\n\n"
        << headline(run) << "\n\n"
        << "drm's figure over each peer's, geometric mean of the per-mesh ratios over the meshes both encode "
        << "(below 1: drm smaller or faster); \"conn smaller\" counts the meshes where drm's connectivity is the "
        << "smaller:\n\n"
        << toMarkdown(summaryTable(run)) << "\n"
        << "## Plots\n\n"
        << "Drawn by `tools/bench/make_plots.py` (python3-matplotlib) from this run's CSV "
        << "(`--csv docs/data/peers.csv`), plus the subdivided meshes of `tools/bench/measure_scale.py` for the "
        << "largest sizes:\n\n"
        << "```sh\npython3 tools/bench/make_plots.py    # docs/images/peers-connectivity.png, "
        << "docs/images/time-per-triangle.png\n```\n\n"
        << "This file, its data, the scale figures and the plots all at once: `bash scripts/make-bench-docs.sh` "
        << "(add `--lock FILE` on a shared machine).\n\n"
        << "![connectivity bits per vertex per mesh](images/peers-connectivity.png)\n\n"
        << "![encode and decode time per triangle against mesh size](images/time-per-triangle.png)\n\n";
    for (Metric metric : kMetrics) {
        out << "## " << metricTitle(metric)
            << (metric == Metric::Encode || metric == Metric::Decode ? " (best of " + std::to_string(run.runs) + ")"
                                                                    : std::string())
            << "\n\n";
        if (metric == Metric::Connectivity)
            out << "\"paper DR\" is the paper's Table 4 figure where the mesh is exactly one of its models. "
                << "A `*` marks a codec whose decoder gave back another triangle count (see the notes).\n\n";
        out << toMarkdown(perMeshTable(run, metric)) << "\n";
    }
    const std::vector<std::string> notes = notesOf(run);
    out << "## Notes\n\n"
        << "Refusals, failures, and decoded vertex or triangle counts that differ from the input (Draco and "
        << "meshoptimizer drop vertices no triangle uses; Draco also splits non-manifold vertices):\n\n";
    if (notes.empty()) out << "- none\n";
    for (const std::string& note : notes) out << "- " << note << "\n";
    return out.str();
}

std::string csvReport(const BenchRun& run) {
    Table table;
    for (const char* title : {"mesh", "vertices", "triangles", "paper_dr_bpv", "codec", "status", "total_bytes",
                              "connectivity_bytes", "connectivity_bpv", "total_bpv", "encode_s", "decode_s",
                              "decoded_vertices", "decoded_triangles"})
        table.addColumn(title, false);
    for (const MeshResult& mesh : run.meshes) {
        for (size_t c = 0; c < run.codecs.size(); ++c) {
            const Measurement& codec = mesh.read ? mesh.codecs[c] : Measurement();
            const bool ok = mesh.read && codec.measured;
            auto number = [&](const std::string& text) { return ok ? text : std::string("-"); };
            table.rows.push_back({mesh.name,
                                  mesh.read ? std::to_string(mesh.vertices) : "-",
                                  mesh.read ? std::to_string(mesh.triangles) : "-",
                                  mesh.hasPaper ? fixed(mesh.paperBpv, 2) : "-",
                                  run.codecs[c],
                                  !mesh.read ? "not read: " + mesh.readError : ok ? "ok" : codec.error,
                                  number(std::to_string(codec.totalBytes)),
                                  number(std::to_string(codec.connectivityBytes)),
                                  number(ok ? fixed(valueOf(mesh, codec, Metric::Connectivity), 4) : ""),
                                  number(ok ? fixed(valueOf(mesh, codec, Metric::Total), 4) : ""),
                                  number(fixed(codec.encodeSeconds, 6)),
                                  number(fixed(codec.decodeSeconds, 6)),
                                  number(std::to_string(codec.decoded.vertices)),
                                  number(std::to_string(codec.decoded.triangles))});
        }
    }
    return toCsv(table);
}

}  // namespace peers
}  // namespace drm
