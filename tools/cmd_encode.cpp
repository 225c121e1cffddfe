// drm encode IN OUT.drm: compress a mesh file.
#include "cli.h"
#include "commands.h"
#include "mesh_input.h"

#include <drm_vcg/file_io.h>

#include <cstdio>

namespace drm {
namespace cli {

const char* const kEncodeHelp =
    "usage: drm encode IN OUT.drm [--bits N] [--predictor P] [--curvature on|off] [--geometry G] [--levers L]\n"
    "                  [--keep-vertex-order]\n"
    "\n"
    "Compresses the triangle mesh IN (PLY, OBJ, OFF or STL) into OUT.drm.\n"
    "Vertex positions are quantized to N bits per axis over the bounding box;\n"
    "connectivity is coded losslessly. Colours, normals and texture coordinates\n"
    "are not kept (a note says so). OUT.drm is written completely or not at all.\n"
    "\n"
    "options:\n"
    "  --bits N          quantization bits per axis, 1..21 (default 12)\n"
    "  --predictor P     apex predictor: auto, parallelogram or midpoint (default auto)\n"
    "  --curvature on|off  the paper's curvature correction (default off)\n"
    "  --geometry G      vertex coder: tree, refine or raw (default tree); refine\n"
    "                    codes the coarse grid first, ranks on it, then the low bits\n"
    "                    predicted across the decoded triangles (docs/format.md)\n"
    "  --refine-bits K   low bits the refine coder codes, 1..8 (default: tries 1..5\n"
    "                    and the tree alone, keeps the smallest)\n"
    "  --levers L        additions to the paper's method: all (default), none, or\n"
    "                    a list of filter, gap, context, angle (see docs/format.md);\n"
    "                    by default meshes under 20000 faces also try none\n"
    "  --keep-vertex-order  also store the input's vertex order, so that decoding\n"
    "                    gives vertices back in input order (costs bits)\n";

int runEncode(const std::vector<std::string>& args) {
    const Arguments parsed = parseArguments("encode", args, encodeOptionNames(), encodeFlagNames());
    parsed.expectPositional(2, 2, "an input mesh and an output .drm file");
    const std::string& input = parsed.positional[0];
    const std::string& output = parsed.positional[1];
    drm::EncodeOptions options = encodeOptionsFrom(parsed);

    const drm::vcgio::LoadedMesh loaded = loadMeshForEncoding(input);
    drm::Encoded encoded;
    {
        ProgressBar bar("encoding " + fileName(input));
        options.progress = bar.callback();
        try {
            encoded = drm::encode(loaded.mesh, options);
        } catch (const drm::Error& e) {
            throw drm::Error("cannot encode " + input + ": " + e.what());
        }
    }
    drm::vcgio::writeFileAtomically(output, encoded.bytes);
    printNotes(loaded.notes);
    const std::string repairs = repairsOf(encoded.stats);
    if (!repairs.empty()) printNote(input + ": " + repairs);
    std::printf("%s -> %s: %s\n", input.c_str(), output.c_str(), summaryOf(encoded.stats).c_str());
    return 0;
}

}  // namespace cli
}  // namespace drm
