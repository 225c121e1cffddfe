// drm ranks IN OUT.ply: faces coloured by the distance rank that created
// them, for looking at where the coder pays (the paper's Figure 1).
#include "cli.h"
#include "commands.h"
#include "mesh_input.h"
#include "ranked_mesh.h"

#include <drm_vcg/mesh_io.h>
#include <drm_vcg/rank_palette.h>

#include <cstdio>

namespace drm {
namespace cli {

const char* const kRanksHelp =
    "usage: drm ranks IN OUT.ply [--bits N] [--predictor P] [--curvature on|off] [--geometry G] [--levers L]\n"
    "                 [--keep-vertex-order]\n"
    "\n"
    "Writes IN as a PLY mesh whose faces are coloured by the rank code that\n"
    "created them (dark grey: a component's start triangle, pale blue-grey:\n"
    "rank 1, green: 2, orange: 3, red: 4 and above); the rank itself is stored\n"
    "as face quality. Prints how many faces each colour has.\n"
    "\n"
    "IN is a mesh (it is encoded with the options given, as 'drm encode' would)\n"
    "or a .drm file (it is decoded, and each face gets the rank stored for it\n"
    "in the file; options cannot be given).\n";

int runRanks(const std::vector<std::string>& args) {
    const Arguments parsed = parseArguments("ranks", args, encodeOptionNames(), encodeFlagNames());
    parsed.expectPositional(2, 2, "an input mesh or .drm file and an output .ply file");
    const std::string& input = parsed.positional[0];
    const std::string& output = parsed.positional[1];

    ProgressBar bar("ranks");
    RankedMesh ranked = loadRankedMesh(input, parsed, bar);
    const drm::Mesh& mesh = ranked.mesh;
    bar.clear();

    drm::vcgio::FaceAttributes attributes;
    attributes.rgb.reserve(3 * mesh.faceCount());
    attributes.quality.reserve(mesh.faceCount());
    std::vector<uint64_t> facesPerBucket(drm::vcgio::kRankBucketCount, 0);
    for (uint32_t rank : ranked.faceRank) {
        const drm::vcgio::RankColour colour = drm::vcgio::rankColour(rank);
        attributes.rgb.insert(attributes.rgb.end(), {colour.r, colour.g, colour.b});
        attributes.quality.push_back(float(rank));
        ++facesPerBucket[size_t(drm::vcgio::rankBucket(rank))];
    }
    drm::vcgio::savePly(output, mesh, &attributes);

    printNotes(ranked.notes);
    std::printf("%s -> %s: %zu faces coloured by the rank that created them\n", input.c_str(), output.c_str(),
                mesh.faceCount());
    for (int bucket = 0; bucket < drm::vcgio::kRankBucketCount; ++bucket) {
        const drm::vcgio::RankColour colour = drm::vcgio::rankBucketColour(bucket);
        const double share = mesh.faceCount() ? 100.0 * double(facesPerBucket[size_t(bucket)]) / double(mesh.faceCount()) : 0.0;
        std::printf("  %-15s #%02x%02x%02x %10llu %7s%%\n", drm::vcgio::rankBucketName(bucket), colour.r, colour.g,
                    colour.b, (unsigned long long)facesPerBucket[size_t(bucket)], fixed(share, 2).c_str());
    }
    return 0;
}

}  // namespace cli
}  // namespace drm
