// drm-peer-bench FILES|DIR: drm against Draco, meshoptimizer + zstd and
// OpenCTM on the same meshes at the same quantization (docs/peers.md).
#include "measure.h"
#include "peer.h"
#include "report.h"

#include "../paper_results.h"

#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace {

const char* const kUsage =
    "usage: drm-peer-bench FILES...|DIR [--csv F] [--markdown F] [--bits N] [--runs N]\n"
    "\n"
    "Runs every mesh (every .ply, .obj, .off and .stl file of a directory, in\n"
    "name order) through drm (default options, and the paper's method), Draco\n"
    "Edgebreaker at compression levels 10 and 7, meshoptimizer's index and\n"
    "vertex codecs with zstd, and OpenCTM MG2, all at N-bit quantization\n"
    "(default 12). Prints connectivity and total bits per vertex, encode and\n"
    "decode times (best of --runs, default 3) and drm's ratios to the peers.\n"
    "\n"
    "  --csv F        also write one row per mesh and codec as CSV to F\n"
    "  --markdown F   also write the whole report as a Markdown document to F\n";

struct Options {
    std::vector<std::string> inputs;
    std::string csv, markdown;
    int bits = 12;
    int runs = 3;
};

int parsePositive(const std::string& option, const std::string& text, int max) {
    size_t used = 0;
    int value = 0;
    try {
        value = std::stoi(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || value < 1 || value > max)
        throw std::invalid_argument(option + " wants a whole number from 1 to " + std::to_string(max) + ", not '" + text + "'");
    return value;
}

Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--csv") options.csv = value();
        else if (arg == "--markdown") options.markdown = value();
        // meshoptimizer's 4 x uint16 positions hold at most 16 bits.
        else if (arg == "--bits") options.bits = parsePositive(arg, value(), 16);
        else if (arg == "--runs") options.runs = parsePositive(arg, value(), 100);
        else if (arg.compare(0, 2, "--") == 0) throw std::invalid_argument("unknown option " + arg);
        else options.inputs.push_back(arg);
    }
    if (options.inputs.empty()) throw std::invalid_argument("no mesh files or directory given");
    return options;
}

std::vector<std::string> meshFiles(const std::vector<std::string>& inputs) {
    std::vector<std::string> files;
    for (const std::string& input : inputs) {
        if (!std::filesystem::is_directory(input)) {
            files.push_back(input);  // a missing file becomes a "not read" row
            continue;
        }
        std::vector<std::string> found;
        for (const auto& entry : std::filesystem::directory_iterator(input))
            if (entry.is_regular_file() && drm::vcgio::isMeshFileName(entry.path().string()))
                found.push_back(entry.path().string());
        std::sort(found.begin(), found.end());
        files.insert(files.end(), found.begin(), found.end());
    }
    return files;
}

std::string commandLine(int argc, char** argv) {
    std::string line = "build/bin/drm-peer-bench";
    for (int i = 1; i < argc; ++i) line += std::string(" ") + argv[i];
    return line;
}

int run(int argc, char** argv) {
    const Options options = parseOptions(argc, argv);
    std::vector<std::unique_ptr<drm::peers::Peer>> peers;
    peers.push_back(drm::peers::makeDrmPeer(false, options.bits));
    peers.push_back(drm::peers::makeDrmPeer(true, options.bits));
    peers.push_back(drm::peers::makeDracoPeer(10, options.bits));
    peers.push_back(drm::peers::makeDracoPeer(7, options.bits));
    peers.push_back(drm::peers::makeMeshoptPeer(options.bits, 19));
    peers.push_back(drm::peers::makeOpenctmPeer(options.bits));

    drm::peers::BenchRun bench;
    bench.bits = options.bits;
    bench.runs = options.runs;
    bench.command = commandLine(argc, argv);
    for (const auto& peer : peers) {
        bench.codecs.push_back(peer->name());
        bench.descriptions.push_back(peer->description());
    }

    const std::vector<std::string> files = meshFiles(options.inputs);
    if (files.empty()) throw std::invalid_argument("no .ply, .obj, .off or .stl files in " + options.inputs[0]);
    for (size_t i = 0; i < files.size(); ++i) {
        drm::peers::MeshResult result;
        result.name = std::filesystem::path(files[i]).filename().string();
        std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, files.size(), result.name.c_str());
        result.hasPaper = drm::cli::paperConnectivityBitsPerVertex(std::filesystem::path(files[i]).stem().string(),
                                                                   result.paperBpv);
        drm::Mesh mesh;
        try {
            mesh = drm::vcgio::loadMesh(files[i]).mesh;
            result.read = true;
        } catch (const std::exception& e) {
            result.readError = e.what();
        }
        if (result.read) {
            result.vertices = mesh.vertexCount();
            result.triangles = mesh.faceCount();
            for (const auto& peer : peers) result.codecs.push_back(drm::peers::measure(*peer, mesh, options.runs));
        }
        bench.meshes.push_back(std::move(result));
    }

    std::fputs(drm::peers::textReport(bench).c_str(), stdout);
    std::fflush(stdout);
    if (!options.csv.empty())
        drm::vcgio::writeFileAtomically(options.csv, [&](std::ostream& out) { out << drm::peers::csvReport(bench); });
    if (!options.markdown.empty())
        drm::vcgio::writeFileAtomically(options.markdown,
                                        [&](std::ostream& out) { out << drm::peers::markdownReport(bench); });
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "help")) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    try {
        return run(argc, argv);
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "drm-peer-bench: error: %s\n%s", e.what(), kUsage);
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "drm-peer-bench: error: %s\n", e.what());
        return 1;
    }
}
