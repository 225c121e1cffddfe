// drm decode IN.drm OUT.ply, or drm decode INPUTS... -o DIR: decompress to
// mesh files.
#include "batch.h"
#include "cli.h"
#include "commands.h"
#include "mesh_input.h"

#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace drm {
namespace cli {

const char* const kDecodeHelp =
    "usage: drm decode IN.drm OUT.ply|OUT.obj [--index auto|grid|flann] [--threads N]\n"
    "       drm decode INPUTS... -o DIR [-j N] [--format ply|obj] [--index auto|grid|flann]\n"
    "\n"
    "Decompresses IN.drm into a mesh file, by OUT's extension: binary PLY\n"
    "(float x, y, z per vertex, triangles, and the attributes the file carries\n"
    "under the names MeshLab reads: nx ny nz, red green blue alpha, quality,\n"
    "texture_u texture_v, face texcoord, texnumber, colour, quality, comment\n"
    "TextureFile) or OBJ (v with colours, vt, vn, usemtl groups, and the .mtl\n"
    "file as OUT.mtl beside OUT.obj: no other file is written). What the format\n"
    "cannot hold is named in a note. Texture images are not in .drm files: keep\n"
    "them beside the output. Vertices come out in the order the file stores\n"
    "them: the input's order if it was encoded with --keep-vertex-order.\n"
    "OUT is written completely or not at all.\n"
    "\n"
    "With -o DIR, every input is decompressed into DIR/NAME.ply (NAME: the\n"
    "input's name without its extension; DIR is created if missing). An input\n"
    "may be a folder: its .drm files, in name order (not recursive). Files are\n"
    "spread over N worker threads; a line is printed as each file finishes, then\n"
    "a summary. A file that fails is reported, naming it, and the others are\n"
    "still written; the exit code is then 1.\n"
    "\n"
    "options:\n"
    "  -o, --output-dir DIR  write DIR/NAME.ply for every input (several inputs, folders)\n"
    "  --format F        with -o: ply (default) or obj\n"
    "  -j, --jobs N      files decoded at once with -o (default: the number of cores)\n"
    "  --index I         spatial index for the neighbour searches: auto (default:\n"
    "                    the faster), grid or flann (FLANN's kd-tree); the decoded\n"
    "                    mesh is the same whichever runs\n"
    "  --threads N       threads for one file: 1, or 2 (the default where the machine\n"
    "                    has several cores: a file whose connectivity comes in two\n"
    "                    parts, as drm writes meshes of 32,768 faces and more,\n"
    "                    decodes them side by side); with -o and more than one job,\n"
    "                    each file takes one; never changes the decoded mesh\n";

namespace {

struct DecodedFile {
    std::vector<std::string> notes;  // what OUT's format cannot hold
    std::string line;  // "IN -> OUT: V ..., F ..."
    uint64_t bytes = 0;
};

// Reads, decodes and writes one file; throws drm::Error naming the input.
DecodedFile decodeFile(const std::string& input, const std::string& output, drm::NeighbourIndex index, int threads,
                       ProgressBar* bar) {
    drm::vcgio::refuseOverwritingInput(input, output);
    if (hasExtension(output, ".obj")) drm::vcgio::refuseOverwritingInput(input, drm::vcgio::objLibraryPath(output));
    const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(input);
    drm::Decoded decoded;
    try {
        drm::DecodeOptions options;
        options.index = index;
        options.threads = threads;
        if (bar) options.progress = bar->callback();
        decoded = drm::decode(bytes.data(), bytes.size(), options);
    } catch (const drm::Error& e) {
        throw drm::Error(e.kind(), "cannot decode " + input + ": " + e.what());
    }
    if (bar) bar->clear();
    DecodedFile result;
    result.notes = drm::vcgio::saveMesh(output, decoded.mesh);
    result.line = input + " -> " + output + ": V " + std::to_string(decoded.stats.vertices) + ", F " +
                  std::to_string(decoded.stats.faces);
    result.bytes = fileBytes(output);
    return result;
}

bool isDrmFileName(const std::string& name) { return hasExtension(name, ".drm"); }

}  // namespace

int runDecode(const std::vector<std::string>& args) {
    std::vector<std::string> valued = batchOptionNames();
    valued.push_back("--format");
    valued.push_back("--index");
    valued.push_back("--threads");
    const Arguments parsed = parseArguments("decode", args, valued, {});
    const std::string format = parsed.value("--format", "ply");
    if (format != "ply" && format != "obj") throw UsageError("--format takes ply or obj, not '" + format + "'");
    const drm::NeighbourIndex index = neighbourIndexFrom(parsed);
    if (parsed.has("-o") && parsed.has("--output-dir")) throw UsageError("give -o or --output-dir, not both");
    const int jobs = jobsFrom(parsed);
    int threads = 0;
    if (parsed.has("--threads")) {
        threads = wholeNumberOption(parsed, "--threads");
        if (threads < 1 || threads > 2) throw UsageError("--threads takes 1 or 2");
    }
    if (parsed.has("-o") || parsed.has("--output-dir")) {
        parsed.expectPositional(1, size_t(-1), "input .drm files or folders");
        const std::string dir = parsed.has("-o") ? parsed.value("-o") : parsed.value("--output-dir");
        const std::vector<std::string> inputs = collectInputs(parsed.positional, isDrmFileName, ".drm files");
        const std::vector<std::string> outputs = outputPaths(inputs, dir, "." + format);
        std::vector<BatchFile> files;
        for (size_t i = 0; i < inputs.size(); ++i) files.push_back({inputs[i], outputs[i], fileBytes(inputs[i])});
        // Several files at once: one thread each, as encoding does.
        const int perFile = std::min<size_t>(size_t(std::max(1, jobs)), files.size()) > 1 ? 1 : threads;
        runBatch({"decoded", "bytes out", true}, files, jobs, [index, perFile](const BatchFile& file) {
            FileOutcome outcome;
            try {
                const DecodedFile decoded = decodeFile(file.input, file.output, index, perFile, nullptr);
                outcome.ok = true;
                outcome.line = decoded.line;
                outcome.notes = decoded.notes;
                outcome.bytesOut = decoded.bytes;
            } catch (const std::exception& e) {
                outcome.error = e.what();
            }
            return outcome;
        });
        return 0;
    }
    if (parsed.has("--format")) throw UsageError("--format goes with -o DIR; otherwise OUT's extension says the format");
    expectInputAndOutput(parsed, "decode", "an input .drm file and an output .ply or .obj file");
    const std::string& input = parsed.positional[0];
    const std::string& output = parsed.positional[1];
    ProgressBar bar("decoding " + fileName(input));
    if (!hasExtension(output, ".ply") && !hasExtension(output, ".obj"))
        throw UsageError("the output must be a .ply or .obj file, not '" + output + "'");
    const DecodedFile decoded = decodeFile(input, output, index, threads, &bar);
    printNotes(decoded.notes);
    std::printf("%s\n", decoded.line.c_str());
    return 0;
}

}  // namespace cli
}  // namespace drm
