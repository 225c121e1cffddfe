// drm encode IN OUT.drm, or drm encode INPUTS... -o DIR: compress mesh files.
#include "batch.h"
#include "cli.h"
#include "commands.h"
#include "mesh_input.h"

#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>

#include <cstdio>
#include <filesystem>

namespace drm {
namespace cli {

const char* const kEncodeHelp =
    "usage: drm encode IN OUT.drm [--bits N] [--predictor P] [--curvature on|off] [--geometry G] [--levers L]\n"
    "                  [--keep-vertex-order] [--attributes LIST|all|none] [--normal-bits N] [--uv-bits N]\n"
    "                  [--weld auto|on|off] [--index auto|grid|flann] [--start search|smallest] [--parts P]\n"
    "                  [--connectivity auto|ranks|topological] [--verify]\n"
    "       drm encode INPUTS... -o DIR [-j N] [options as above]\n"
    "\n"
    "Compresses the triangle mesh IN (PLY, OBJ, OFF or STL) into OUT.drm.\n"
    "Vertex positions are quantized to N bits per axis over the bounding box;\n"
    "connectivity is coded losslessly. What the file carries besides is kept by\n"
    "default: vertex colours (exact), normals (to --normal-bits), texture\n"
    "coordinates per vertex or per corner (to --uv-bits), vertex and face quality,\n"
    "face colours, OBJ materials and the statements of their .mtl file (read\n"
    "only inside the OBJ's folder or below it), texture file names. What cannot\n"
    "be kept (custom PLY properties, per-face normals, ...) is named in a note.\n"
    "OUT.drm is written completely or not at all, and never over IN.\n"
    "\n"
    "With -o DIR, every input is compressed into DIR/NAME.drm (NAME: the input's\n"
    "name without its extension; DIR is created if missing). An input may be a\n"
    "folder: its .ply, .obj, .off and .stl files, in name order (not recursive).\n"
    "Files are spread over N worker threads, one file each at a time; a line is\n"
    "printed as each file finishes, then a summary (files, bytes in and out,\n"
    "compression ratio, wall time). A file that fails is reported, naming it, and\n"
    "the others are still written; the exit code is then 1. Each output is the\n"
    "same file a single 'drm encode IN OUT.drm' writes.\n"
    "\n"
    "options:\n"
    "  --bits N          quantization bits per axis, {bits} (default {default-bits})\n"
    "  --predictor P     apex predictor: {predictors} (default {default-predictor})\n"
    "  --curvature on|off  the paper's curvature correction (default off)\n"
    "  --geometry G      vertex coder: {geometry-coders} (default {default-geometry}); refine\n"
    "                    codes the coarse grid first, ranks on it, then the low bits\n"
    "                    predicted across the decoded triangles (docs/format.md);\n"
    "                    auto codes the tree, and where it costs over {auto-refine-above} bits per\n"
    "                    vertex also refine with {auto-refine-low-bits} low bits, kept where {auto-refine-gain} %\n"
    "                    smaller (it decodes 20-30 % slower); under 8192 vertices,\n"
    "                    tried where an estimate promises about 1 %, kept wherever\n"
    "                    smaller (under 1000, tried wherever it may be smaller)\n"
    "  --refine-bits K   low bits the refine coder codes, {refine-bits} (default: tries {tried-refine-bits}\n"
    "                    and the tree alone, keeps the smallest)\n"
    "  --connectivity C  connectivity coder: auto (default) codes the paper's distance\n"
    "                    ranks and also the topological coder (a new vertex, a fan's\n"
    "                    far end or another front vertex per triangle, positions in\n"
    "                    the order met: sliver-rich CAD meshes take far fewer bits)\n"
    "                    and keeps the smaller file (a mesh with vertices of\n"
    "                    thousands of faces: topological alone); ranks or\n"
    "                    topological alone\n"
    "  --levers L        additions to the paper's method: all (default), none, or\n"
    "                    a list of {levers} (see docs/format.md);\n"
    "                    by default meshes under 4096 faces also try none\n"
    "  --keep-vertex-order  also store the input's vertex order, so that decoding\n"
    "                    gives vertices back in input order (costs bits)\n"
    "  --attributes L    attributes to keep: all (default), none, or a list of\n"
    "                    colors, normals, texcoords, quality, corner-texcoords,\n"
    "                    corner-normals, face-colors, face-quality, materials,\n"
    "                    textures, metadata\n"
    "  --normal-bits N   normal quantization, {normal-bits} bits (default {default-normal-bits}: within 0.2 degrees)\n"
    "  --uv-bits N       texture coordinate quantization over their range, {uv-bits} bits\n"
    "                    (default {default-uv-bits}: within half a step of 1/4095 of the range)\n"
    "  --weld W          auto (default), on or off: merge a mesh's vertices repeating\n"
    "                    a grid point (a vertex per corner, as some exporters write)\n"
    "                    for the connectivity, keeping each corner's attributes\n"
    "  --index I         spatial index for the neighbour searches: auto (default:\n"
    "                    the faster per search), grid or flann (FLANN's kd-tree);\n"
    "                    the file is the same byte for byte whichever runs\n"
    "  --start S         where the traversal starts each component: search (default:\n"
    "                    meshes under 20000 faces also try another first\n"
    "                    vertex and the input's face order, each over Morton\n"
    "                    numbering and the vertex coder's, and keep the smallest\n"
    "                    file) or smallest (each at its smallest vertex, Morton\n"
    "                    numbering, faster)\n"
    "  --parts P         the connectivity in two parts that decode side by side on\n"
    "                    two cores: auto (default: meshes of 32,768 faces and more,\n"
    "                    unless their seam would be long), 1 or 2\n"
    "  --threads N       threads for one mesh: 1, or 2 (the default where the machine\n"
    "                    has several cores: the vertex coder beside the mesh checks\n"
    "                    and the connectivity, refine's estimates and attempts beside\n"
    "                    the tree's attempt); with -o and\n"
    "                    more than one job, each file takes one; never changes the file\n"
    "  --verify          decode the new file and compare it with the mesh before\n"
    "                    writing it; a difference is an error and nothing is written\n"
    "                    (costs about half the encoding time again)\n"
    "  -o, --output-dir DIR  write DIR/NAME.drm for every input (several inputs, folders)\n"
    "  -j, --jobs N      files encoded at once with -o (default: the number of cores)\n";

namespace {

struct EncodedFile {
    std::vector<std::string> notes;  // about the file as read
    std::string repairs;             // what the codec repaired, or ""
    std::string line;  // "IN -> OUT: summary"
    uint64_t bytes = 0;
};

// Reads, encodes and writes one file; throws drm::Error naming the input.
// alone: the only mesh this process encodes (not a batch's).
EncodedFile encodeFile(const std::string& input, const std::string& output, drm::EncodeOptions options,
                       ProgressBar* bar, bool alone) {
    drm::vcgio::refuseOverwritingInput(input, output);
    const drm::vcgio::LoadedMesh loaded = loadMeshForEncoding(input);
    for (const std::string& read : loaded.otherFilesRead) drm::vcgio::refuseOverwritingInput(read, output);
    if (alone) mapLargeBlocksApart(loaded.mesh.vertexCount());
    drm::Encoded encoded;
    if (bar) options.progress = bar->callback();
    try {
        encoded = drm::encode(loaded.mesh, options);
    } catch (const drm::Error& e) {
        throw drm::Error(e.kind(), "cannot encode " + input + ": " + e.what());
    }
    if (bar) bar->clear();
    drm::vcgio::writeFileAtomically(output, encoded.bytes);
    EncodedFile result;
    result.notes = loaded.notes;
    for (const std::string& note : attributesNotKept(loaded.mesh, options, encoded.stats)) result.notes.push_back(note);
    result.repairs = repairsOf(encoded.stats);
    result.line = input + " -> " + output + ": " + summaryOf(encoded.stats);
    result.bytes = encoded.bytes.size();
    return result;
}

int encodeMany(const Arguments& parsed, const drm::EncodeOptions& options) {
    const std::string dir = parsed.has("-o") ? parsed.value("-o") : parsed.value("--output-dir");
    const int jobs = jobsFrom(parsed);
    const std::vector<std::string> inputs =
        collectInputs(parsed.positional, [](const std::string& name) { return drm::vcgio::isMeshFileName(name); },
                      ".ply, .obj, .off or .stl files");
    const std::vector<std::string> outputs = outputPaths(inputs, dir, ".drm");
    std::vector<BatchFile> files;
    for (size_t i = 0; i < inputs.size(); ++i) files.push_back({inputs[i], outputs[i], fileBytes(inputs[i])});
    const drm::EncodeOptions perFile = perFileOptions(options, jobs, files.size());
    runBatch({"encoded", "bytes out", false}, files, jobs, [&](const BatchFile& file) {
        FileOutcome outcome;
        try {
            const EncodedFile encoded = encodeFile(file.input, file.output, perFile, nullptr, false);
            outcome.ok = true;
            outcome.line = encoded.line;
            outcome.notes = encoded.notes;
            if (!encoded.repairs.empty()) outcome.notes.push_back(encoded.repairs);
            outcome.bytesOut = encoded.bytes;
        } catch (const std::exception& e) {
            outcome.error = e.what();
        }
        return outcome;
    });
    return 0;
}

}  // namespace

int runEncode(const std::vector<std::string>& args) {
    std::vector<std::string> valued = encodeOptionNames();
    for (const std::string& name : batchOptionNames()) valued.push_back(name);
    const Arguments parsed = parseArguments("encode", args, valued, encodeFlagNames());
    drm::EncodeOptions options = encodeOptionsFrom(parsed);
    if (parsed.has("-o") && parsed.has("--output-dir")) throw UsageError("give -o or --output-dir, not both");
    if (parsed.has("-o") || parsed.has("--output-dir")) {
        parsed.expectPositional(1, size_t(-1), "input meshes or folders");
        return encodeMany(parsed, options);
    }
    jobsFrom(parsed);  // a malformed -j is an error even where it does not matter
    expectInputAndOutput(parsed, "encode", "an input mesh and an output .drm file");
    const std::string& input = parsed.positional[0];
    const std::string& output = parsed.positional[1];

    shareOneMallocArena();
    ProgressBar bar("encoding " + fileName(input));
    const EncodedFile encoded = encodeFile(input, output, options, &bar, true);
    printNotes(encoded.notes);
    if (!encoded.repairs.empty()) printNote(input + ": " + encoded.repairs);
    std::printf("%s\n", encoded.line.c_str());
    return 0;
}

}  // namespace cli
}  // namespace drm
