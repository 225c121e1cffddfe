// Ranks of a mesh or of a .drm file (see ranked_mesh.h).
#include "ranked_mesh.h"

#include "mesh_input.h"

#include <drm_vcg/file_io.h>

namespace drm {
namespace cli {

RankedMesh decodeRankedMesh(const std::string& input, ProgressBar& bar) {
    const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(input);
    drm::Decoded decoded;
    try {
        decoded = drm::decode(bytes, bar.callback());
    } catch (const drm::Error& e) {
        throw drm::Error(e.kind(), "cannot decode " + input + ": " + e.what());
    }
    if (decoded.stats.connectivity == drm::ConnectivityCoder::Topological)
        throw drm::Error(drm::ErrorKind::InvalidInput, input + " codes its connectivity topologically and has no distance ranks; "
                         "give the mesh itself, or a file written with --connectivity ranks");
    RankedMesh ranked;
    ranked.mesh = std::move(decoded.mesh);
    ranked.faceRank = std::move(decoded.faceRank);  // the decoder reports the code of every face
    ranked.stats = std::move(decoded.stats);
    return ranked;
}

RankedMesh loadRankedMesh(const std::string& input, const Arguments& parsed, ProgressBar& bar) {
    if (hasExtension(input, ".drm")) {
        std::vector<std::string> encodeOptions = encodeOptionNames();
        encodeOptions.insert(encodeOptions.end(), encodeFlagNames().begin(), encodeFlagNames().end());
        for (const std::string& option : encodeOptions)
            if (parsed.has(option))
                throw UsageError(option + " cannot be given with a .drm input: its own options are used");
        return decodeRankedMesh(input, bar);
    }
    drm::EncodeOptions options = encodeOptionsFrom(parsed);
    // Ranks are what is shown: the distance-rank coder, whichever file is smaller.
    if (options.connectivity == drm::ConnectivityCoder::Topological)
        throw UsageError("--connectivity topological codes no distance ranks to show");
    options.connectivity = drm::ConnectivityCoder::Ranks;
    drm::vcgio::LoadedMesh loaded = loadMeshForEncoding(input);
    RankedMesh ranked;
    ranked.mesh = std::move(loaded.mesh);
    ranked.notes = std::move(loaded.notes);
    options.progress = bar.callback();
    try {
        drm::Encoded encoded = drm::encode(ranked.mesh, options);
        ranked.faceRank = std::move(encoded.faceRank);
        ranked.stats = std::move(encoded.stats);
    } catch (const drm::Error& e) {
        throw drm::Error(e.kind(), "cannot encode " + input + ": " + e.what());
    }
    return ranked;
}

}  // namespace cli
}  // namespace drm
