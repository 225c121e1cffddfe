// drm decode IN.drm OUT.ply: decompress to a mesh file.
#include "cli.h"
#include "commands.h"

#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>

#include <cstdio>

namespace drm {
namespace cli {

const char* const kDecodeHelp =
    "usage: drm decode IN.drm OUT.ply\n"
    "\n"
    "Decompresses IN.drm into a binary PLY mesh (float x, y, z per vertex,\n"
    "triangles). Vertices come out in the order the file stores them: the\n"
    "input's order if it was encoded with --keep-vertex-order.\n"
    "OUT.ply is written completely or not at all.\n";

int runDecode(const std::vector<std::string>& args) {
    const Arguments parsed = parseArguments("decode", args, {}, {});
    parsed.expectPositional(2, 2, "an input .drm file and an output .ply file");
    const std::string& input = parsed.positional[0];
    const std::string& output = parsed.positional[1];

    const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(input);
    drm::Decoded decoded;
    {
        ProgressBar bar("decoding " + fileName(input));
        try {
            decoded = drm::decode(bytes, bar.callback());
        } catch (const drm::Error& e) {
            throw drm::Error("cannot decode " + input + ": " + e.what());
        }
    }
    drm::vcgio::savePly(output, decoded.mesh);
    std::printf("%s -> %s: V %llu, F %llu\n", input.c_str(), output.c_str(),
                (unsigned long long)decoded.stats.vertices, (unsigned long long)decoded.stats.faces);
    return 0;
}

}  // namespace cli
}  // namespace drm
