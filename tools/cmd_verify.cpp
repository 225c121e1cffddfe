// drm verify INPUTS...: encode and decode in memory, check the round trip.
#include "batch.h"
#include "cli.h"
#include "commands.h"
#include "file_census.h"
#include "lossless_check.h"
#include "mesh_input.h"

#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>

#include <cstdio>
#include <filesystem>

namespace drm {
namespace cli {

const char* const kVerifyHelp =
    "usage: drm verify IN [--bits N] [--predictor P] [--curvature on|off] [--geometry G] [--levers L]\n"
    "                 [--keep-vertex-order] [--attributes L] [--normal-bits N] [--uv-bits N] [--weld W]\n"
    "       drm verify INPUTS... [-j N] [options as above]\n"
    "\n"
    "Encodes the mesh IN in memory, decodes the result and checks that nothing\n"
    "but quantization changed: every decoded vertex sits on its input vertex's\n"
    "grid point, and the decoded triangles are the input's, with the same\n"
    "orientation. The attributes kept (see --attributes) are compared corner by\n"
    "corner and face by face: colours, quality, face colours, materials and\n"
    "names exactly, normals within the angle --normal-bits allows (0.2 degrees\n"
    "at 10 bits), texture coordinates within half a --uv-bits step of their\n"
    "range. The mesh as read is first checked against a separate count of the\n"
    "vertices and triangles the file itself describes, so a reader that drops\n"
    "part of a file is not reported lossless. Exits with 0 only when the round\n"
    "trip is lossless.\n"
    "Options as for 'drm encode'.\n"
    "\n"
    "Several inputs, or a folder (its .ply, .obj, .off and .stl files, in name\n"
    "order), are checked on N worker threads; a line is printed as each file\n"
    "finishes, then a summary. The exit code is 1 if any file failed.\n"
    "\n"
    "options:\n"
    "  -j, --jobs N      files checked at once (default: the number of cores)\n";

namespace {

struct VerifiedFile {
    std::vector<std::string> notes;
    std::string repairs;
    std::string line;  // "IN: summary: lossless"
    uint64_t bytes = 0;
};

// Throws drm::Error naming the input unless the round trip is lossless.
VerifiedFile verifyFile(const std::string& input, drm::EncodeOptions options, ProgressBar* bar) {
    const drm::vcgio::LoadedMesh loaded = loadMeshForEncoding(input);
    const std::string readerLoss = censusMismatch(takeCensus(input, drm::vcgio::readFileBytes(input)),
                                                  loaded.mesh.vertexCount(), loaded.mesh.faceCount());
    if (!readerLoss.empty())
        throw drm::Error(drm::ErrorKind::InvalidInput, input + " is not read whole: " + readerLoss);
    if (bar) bar->setLabel("encoding " + fileName(input));
    if (bar) options.progress = bar->callback();
    drm::Encoded encoded;
    try {
        encoded = drm::encode(loaded.mesh, options);
    } catch (const drm::Error& e) {
        throw drm::Error(e.kind(), "cannot encode " + input + ": " + e.what());
    }
    if (bar) bar->setLabel("decoding " + fileName(input));
    drm::Decoded decoded;
    try {
        decoded = drm::decode(encoded.bytes, bar ? bar->callback() : drm::Progress());
    } catch (const drm::Error& e) {
        throw drm::Error(e.kind(), "cannot decode what " + input + " encoded to: " + e.what());
    }
    if (bar) bar->clear();
    std::string mismatch = findLosslessMismatch(loaded.mesh, encoded, decoded);
    if (mismatch.empty()) mismatch = findAttributeMismatch(loaded.mesh, options, encoded, decoded);
    if (!mismatch.empty()) throw drm::Error(drm::ErrorKind::InvalidInput, input + " does not survive encoding losslessly: " + mismatch);
    VerifiedFile result;
    result.notes = loaded.notes;
    result.repairs = repairsOf(encoded.stats);
    result.line = input + ": " + summaryOf(encoded.stats) + ": lossless";
    result.bytes = encoded.bytes.size();
    return result;
}

}  // namespace

int runVerify(const std::vector<std::string>& args) {
    std::vector<std::string> valued = encodeOptionNames();
    valued.push_back("-j");
    valued.push_back("--jobs");
    const Arguments parsed = parseArguments("verify", args, valued, encodeFlagNames());
    parsed.expectPositional(1, size_t(-1), "an input mesh (or several, or a folder)");
    const drm::EncodeOptions options = encodeOptionsFrom(parsed);
    const int jobs = jobsFrom(parsed);
    std::error_code error;
    if (parsed.positional.size() > 1 || std::filesystem::is_directory(parsed.positional[0], error)) {
        const std::vector<std::string> inputs =
            collectInputs(parsed.positional, [](const std::string& name) { return drm::vcgio::isMeshFileName(name); },
                          ".ply, .obj, .off or .stl files");
        std::vector<BatchFile> files;
        for (const std::string& input : inputs) files.push_back({input, "", fileBytes(input)});
        const drm::EncodeOptions perFile = perFileOptions(options, jobs, files.size());
        runBatch({"verified lossless", "bytes encoded", false}, files, jobs, [&](const BatchFile& file) {
            FileOutcome outcome;
            try {
                const VerifiedFile verified = verifyFile(file.input, perFile, nullptr);
                outcome.ok = true;
                outcome.line = verified.line;
                outcome.notes = verified.notes;
                if (!verified.repairs.empty()) outcome.notes.push_back(verified.repairs);
                outcome.bytesOut = verified.bytes;
            } catch (const std::exception& e) {
                outcome.error = e.what();
            }
            return outcome;
        });
        return 0;
    }
    const std::string& input = parsed.positional[0];
    shareOneMallocArena();
    ProgressBar bar("encoding " + fileName(input));
    const VerifiedFile verified = verifyFile(input, options, &bar);
    printNotes(verified.notes);
    if (!verified.repairs.empty()) printNote(input + ": " + verified.repairs);
    std::printf("%s\n", verified.line.c_str());
    return 0;
}

}  // namespace cli
}  // namespace drm
