// drm bench FILES|DIR: rates, rank shares and times over many meshes, as a
// table to read in the terminal or paste into docs (CSV, Markdown).
#include "cli.h"
#include "commands.h"
#include "lossless_check.h"
#include "paper_results.h"

#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace drm {
namespace cli {

const char* const kBenchHelp =
    "usage: drm bench FILES...|DIR [--csv F] [--markdown F] [--bits N] [--predictor P]\n"
    "                 [--curvature on|off] [--geometry G] [--levers L] [--keep-vertex-order]\n"
    "\n"
    "Encodes and decodes each mesh (every .ply, .obj, .off and .stl file of a\n"
    "directory, in name order) and prints one row per mesh: vertices,\n"
    "triangles, components, boundary edges, connectivity bits per vertex, the\n"
    "paper's DR result where the mesh is one of its models (Table 4), the\n"
    "shares of rank-1 and rank-2 codes among all codes (Table 3), the\n"
    "connectivity coder (ranks or topological) and the geometry coder, geometry and\n"
    "total bits per vertex, encode and decode seconds (codec calls only, not\n"
    "file reading), the process's peak resident memory during encoding and\n"
    "during decoding in MiB (Linux; includes the input mesh the bench holds and\n"
    "heap the allocator kept from earlier meshes: a ceiling, exact for the first),\n"
    "and whether the round trip is lossless. A mesh that cannot\n"
    "be read or encoded gets a row with the reason, and the bench goes on; the\n"
    "exit code is 1 if any mesh failed.\n"
    "\n"
    "options:\n"
    "  --csv F        also write the table as CSV to F\n"
    "  --markdown F   also write the table as Markdown to F\n"
    "  --bits, --predictor, --curvature, --geometry, --refine-bits, --keep-vertex-order,\n"
    "  --connectivity\n"
    "                 as for 'drm encode'\n";

namespace {

struct BenchRow {
    std::string name;
    bool measured = false;  // false: `status` says why not
    drm::Stats stats;
    bool hasPaper = false;
    double paperBpv = 0;
    double rank1Share = 0, rank2Share = 0;
    double encodeSeconds = 0, decodeSeconds = 0;
    int64_t encodePeakKb = -1, decodePeakKb = -1;  // -1: not known
    std::string status;  // "ok" or "FAILED: reason"
};

std::vector<std::string> collectMeshFiles(const std::vector<std::string>& paths) {
    std::vector<std::string> files;
    for (const std::string& path : paths) {
        std::error_code error;
        if (std::filesystem::is_directory(path, error)) {
            std::vector<std::string> found;
            for (const auto& entry : std::filesystem::directory_iterator(path, error)) {
                const std::string file = entry.path().string();
                if (drm::vcgio::isMeshFileName(file) && entry.is_regular_file(error)) found.push_back(file);
            }
            if (error) throw drm::Error(drm::ErrorKind::Io, "cannot list " + path + ": " + error.message());
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else {
            files.push_back(path);  // a missing file becomes a failed row
        }
    }
    return files;
}

// The process's peak resident set size (VmHWM) since the last
// resetPeakMemory(), in KiB; -1 where Linux's /proc does not tell.
int64_t peakMemoryKb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.compare(0, 6, "VmHWM:") == 0) return std::atoll(line.c_str() + 6);
    return -1;
}

// Writing 5 to clear_refs resets VmHWM to the current resident size (Linux
// 4.0 and later). False if that failed: peaks are then not per mesh.
bool resetPeakMemory() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.flush();
    return bool(clear);
}

double shareOf(const drm::Stats& stats, size_t rank) {
    uint64_t total = 0;
    for (uint64_t count : stats.rankHistogram) total += count;
    if (total == 0 || rank >= stats.rankHistogram.size()) return 0;
    return double(stats.rankHistogram[rank]) / double(total);
}

BenchRow benchOne(const std::string& path, const drm::EncodeOptions& baseOptions, ProgressBar& bar) {
    BenchRow row;
    row.name = fileName(path);
    row.hasPaper = paperConnectivityBitsPerVertex(fileStem(path), row.paperBpv);
    std::string stage = "reading";
    try {
        const drm::Mesh input = drm::vcgio::loadMesh(path).mesh;
        drm::EncodeOptions options = baseOptions;
        options.progress = bar.callback();
        using Clock = std::chrono::steady_clock;
        stage = "encoding";
        const bool encodePeak = resetPeakMemory();
        const Clock::time_point start = Clock::now();
        const drm::Encoded encoded = drm::encode(input, options);
        const Clock::time_point encodedAt = Clock::now();
        if (encodePeak) row.encodePeakKb = peakMemoryKb();
        stage = "decoding";
        const bool decodePeak = resetPeakMemory();
        const Clock::time_point decodeStart = Clock::now();
        const drm::Decoded decoded = drm::decode(encoded.bytes, bar.callback());
        const Clock::time_point decodedAt = Clock::now();
        if (decodePeak) row.decodePeakKb = peakMemoryKb();
        bar.clear();
        row.encodeSeconds = std::chrono::duration<double>(encodedAt - start).count();
        row.decodeSeconds = std::chrono::duration<double>(decodedAt - decodeStart).count();
        row.stats = encoded.stats;
        row.rank1Share = shareOf(encoded.stats, 1);
        row.rank2Share = shareOf(encoded.stats, 2);
        row.measured = true;
        const std::string mismatch = findLosslessMismatch(input, encoded, decoded);
        row.status = mismatch.empty() ? "ok" : "FAILED: not lossless: " + mismatch;
    } catch (const std::exception& e) {
        bar.clear();
        const std::string reason = e.what();
        // loadMesh's messages already say "cannot read FILE".
        row.status = "FAILED: " + (stage == "reading" ? reason : stage + ": " + reason);
    }
    return row;
}

struct Column {
    const char* title;     // terminal and Markdown
    const char* csvTitle;
    bool numeric;
};

const std::vector<Column>& columns() {
    static const std::vector<Column> list = {
        {"mesh", "mesh", false},
        {"V", "vertices", true},
        {"T", "triangles", true},
        {"comp", "components", true},
        {"bnd", "boundary_edges", true},
        {"conn bpv", "connectivity_bpv", true},
        {"paper DR", "paper_dr_bpv", true},
        {"rank 1", "rank1_share", true},
        {"rank 2", "rank2_share", true},
        {"geom bpv", "geometry_bpv", true},
        {"connectivity", "connectivity_coder", false},
        {"geometry", "geometry_coder", false},
        {"k", "refine_bits", true},
        {"total bpv", "total_bpv", true},
        {"enc s", "encode_s", true},
        {"dec s", "decode_s", true},
        {"enc MiB", "encode_peak_mib", true},
        {"dec MiB", "decode_peak_mib", true},
        {"copies", "vertex_copies", true},
        {"turned", "turned_faces", true},
        {"repeated", "repeated_faces", true},
        {"loose", "loose_faces", true},
        {"repair B", "repair_bytes", true},
        {"lossless", "lossless", false},
    };
    return list;
}

std::vector<std::string> cellsOf(const BenchRow& row) {
    const std::string none = "-";
    const drm::Stats& s = row.stats;
    auto count = [&](uint64_t value) { return row.measured ? std::to_string(value) : none; };
    auto rate = [&](double value, int decimals) { return row.measured ? fixed(value, decimals) : none; };
    return {row.name,
            count(s.vertices),
            count(s.faces),
            count(s.components),
            count(s.boundaryEdges),
            rate(s.connectivityBitsPerVertex(), 3),
            row.hasPaper ? fixed(row.paperBpv, 2) : none,
            rate(row.rank1Share, 3),
            rate(row.rank2Share, 3),
            rate(s.geometryBitsPerVertex(), 3),
            row.measured ? std::string(drm::connectivityCoderName(s.connectivity)) : none,
            !row.measured ? none : s.connectivity == drm::ConnectivityCoder::Topological ? "walk" : std::string(drm::geometryCoderName(s.geometry)),
            count(uint64_t(s.refineBits)),
            rate(s.totalBitsPerVertex(), 3),
            rate(row.encodeSeconds, 3),
            rate(row.decodeSeconds, 3),
            row.measured && row.encodePeakKb >= 0 ? fixed(double(row.encodePeakKb) / 1024, 1) : none,
            row.measured && row.decodePeakKb >= 0 ? fixed(double(row.decodePeakKb) / 1024, 1) : none,
            count(s.splitVertices),
            count(s.flippedFaces),
            count(s.repeatedFaces),
            count(s.looseFaces),
            count(s.repairBytes),
            row.status};
}

std::string terminalTable(const std::vector<BenchRow>& rows) {
    std::vector<std::vector<std::string>> table;
    for (const BenchRow& row : rows) table.push_back(cellsOf(row));
    std::vector<size_t> width;
    for (const Column& column : columns()) width.push_back(std::string(column.title).size());
    for (const auto& cells : table)
        for (size_t c = 0; c + 1 < cells.size(); ++c) width[c] = std::max(width[c], cells[c].size());
    std::ostringstream out;
    auto line = [&](const std::vector<std::string>& cells) {
        for (size_t c = 0; c < cells.size(); ++c) {
            const bool last = c + 1 == cells.size();
            const size_t pad = last ? 0 : width[c] - std::min(width[c], cells[c].size());
            if (c > 0) out << "  ";
            if (columns()[c].numeric) out << std::string(pad, ' ') << cells[c];
            else out << cells[c] << (last ? "" : std::string(pad, ' '));
        }
        out << "\n";
    };
    std::vector<std::string> titles;
    for (const Column& column : columns()) titles.push_back(column.title);
    line(titles);
    for (const auto& cells : table) line(cells);
    return out.str();
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += (c == '"') ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string csvTable(const std::vector<BenchRow>& rows) {
    std::ostringstream out;
    for (size_t c = 0; c < columns().size(); ++c) out << (c ? "," : "") << columns()[c].csvTitle;
    out << "\n";
    for (const BenchRow& row : rows) {
        const std::vector<std::string> cells = cellsOf(row);
        for (size_t c = 0; c < cells.size(); ++c) out << (c ? "," : "") << csvField(cells[c] == "-" ? "" : cells[c]);
        out << "\n";
    }
    return out.str();
}

std::string markdownTable(const std::vector<BenchRow>& rows) {
    std::ostringstream out;
    out << "|";
    for (const Column& column : columns()) out << " " << column.title << " |";
    out << "\n|";
    for (const Column& column : columns()) out << (column.numeric ? "---:|" : "---|");
    out << "\n";
    for (const BenchRow& row : rows) {
        out << "|";
        for (std::string cell : cellsOf(row)) {
            std::string escaped;
            for (char c : cell) escaped += (c == '|') ? std::string("\\|") : std::string(1, c);
            out << " " << escaped << " |";
        }
        out << "\n";
    }
    return out.str();
}

}  // namespace

int runBench(const std::vector<std::string>& args) {
    std::vector<std::string> valued = encodeOptionNames();
    valued.push_back("--csv");
    valued.push_back("--markdown");
    const Arguments parsed = parseArguments("bench", args, valued, encodeFlagNames());
    parsed.expectPositional(1, size_t(-1), "mesh files or a directory");
    const drm::EncodeOptions options = encodeOptionsFrom(parsed);

    const std::vector<std::string> files = collectMeshFiles(parsed.positional);
    if (files.empty()) throw drm::Error(drm::ErrorKind::InvalidInput, "no .ply, .obj, .off or .stl files in " + parsed.positional[0]);

    std::vector<BenchRow> rows;
    ProgressBar bar("");
    for (size_t i = 0; i < files.size(); ++i) {
        bar.setLabel("[" + std::to_string(i + 1) + "/" + std::to_string(files.size()) + "] " + fileName(files[i]));
        rows.push_back(benchOne(files[i], options, bar));
    }
    bar.clear();

    std::fputs(terminalTable(rows).c_str(), stdout);
    std::fflush(stdout);
    if (parsed.has("--csv")) drm::vcgio::writeFileAtomically(parsed.value("--csv"), [&](std::ostream& out) { out << csvTable(rows); });
    if (parsed.has("--markdown"))
        drm::vcgio::writeFileAtomically(parsed.value("--markdown"), [&](std::ostream& out) { out << markdownTable(rows); });

    const size_t failed = size_t(std::count_if(rows.begin(), rows.end(), [](const BenchRow& r) { return r.status != "ok"; }));
    if (failed > 0)
        throw drm::Error(drm::ErrorKind::InvalidInput, std::to_string(failed) + " of " + std::to_string(rows.size()) +
                         " meshes failed (see the table's last column)");
    return 0;
}

}  // namespace cli
}  // namespace drm
