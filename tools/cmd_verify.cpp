// drm verify IN: encode and decode in memory, check the round trip.
#include "cli.h"
#include "commands.h"
#include "lossless_check.h"
#include "mesh_input.h"

#include <cstdio>

namespace drm {
namespace cli {

const char* const kVerifyHelp =
    "usage: drm verify IN [--bits N] [--predictor P] [--curvature on|off] [--geometry G] [--levers L]\n"
    "                 [--keep-vertex-order]\n"
    "\n"
    "Encodes the mesh IN in memory, decodes the result and checks that nothing\n"
    "but quantization changed: every decoded vertex sits on its input vertex's\n"
    "grid point, and the decoded triangles are the input's, with the same\n"
    "orientation. Exits with 0 only when the round trip is lossless.\n"
    "Options as for 'drm encode'.\n";

int runVerify(const std::vector<std::string>& args) {
    const Arguments parsed = parseArguments("verify", args, encodeOptionNames(), encodeFlagNames());
    parsed.expectPositional(1, 1, "one input mesh");
    const std::string& input = parsed.positional[0];
    drm::EncodeOptions options = encodeOptionsFrom(parsed);

    const drm::vcgio::LoadedMesh loaded = loadMeshForEncoding(input);
    ProgressBar bar("encoding " + fileName(input));
    options.progress = bar.callback();
    drm::Encoded encoded;
    try {
        encoded = drm::encode(loaded.mesh, options);
    } catch (const drm::Error& e) {
        throw drm::Error("cannot encode " + input + ": " + e.what());
    }
    bar.setLabel("decoding " + fileName(input));
    drm::Decoded decoded;
    try {
        decoded = drm::decode(encoded.bytes, bar.callback());
    } catch (const drm::Error& e) {
        throw drm::Error("cannot decode what " + input + " encoded to: " + e.what());
    }
    bar.clear();
    const std::string mismatch = findLosslessMismatch(loaded.mesh, encoded, decoded);
    if (!mismatch.empty()) throw drm::Error(input + " does not survive encoding losslessly: " + mismatch);
    printNotes(loaded.notes);
    const std::string repairs = repairsOf(encoded.stats);
    if (!repairs.empty()) printNote(input + ": " + repairs);
    std::printf("%s: %s: lossless\n", input.c_str(), summaryOf(encoded.stats).c_str());
    return 0;
}

}  // namespace cli
}  // namespace drm
