// index_bench MESH.ply [ROLE INDEX REPS]: the two spatial indexes per role,
// for docs/tuning.md (the grid or FLANN for each role).
//   graph:     the geometry tree's 8-nearest graph (nearestOfEach, index
//              built inside), FLANN's batch search on every core;
//   traversal: drm::decode of MESH's default file, every search of the
//              traversal on the index (decoding runs the same searches as
//              encoding, and only the traversal's).
// Without ROLE: a table of wall times, best of 3, both roles, both indexes.
// With ROLE INDEX REPS: that measurement alone, REPS times (INDEX none: only
// the setup), for callgrind.
#include <drmcodec/drmcodec.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "spatial/spatial_index.h"
#include "tiny_ply.h"

namespace {

double seconds(const std::chrono::steady_clock::time_point& start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

drm::NeighbourIndex parseIndex(const std::string& name) {
    return name == "flann" ? drm::NeighbourIndex::Flann : drm::NeighbourIndex::Grid;
}

double runOnce(const std::string& role, drm::NeighbourIndex index, const std::vector<int32_t>& grid,
               const std::vector<uint8_t>& file) {
    const auto start = std::chrono::steady_clock::now();
    if (role == "graph") {
        std::vector<uint32_t> neighbours;  // without distances, as the geometry tree asks
        drm::makeSpatialIndex(grid, index, drm::IndexRole::NeighbourGraph)->nearestOfEach(8, neighbours, nullptr);
    } else {
        drm::DecodeOptions options;
        options.index = index;
        drm::decode(file.data(), file.size(), options);
    }
    return seconds(start);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 && argc != 5) {
        std::fprintf(stderr, "usage: index_bench MESH.ply [graph|traversal grid|flann|none REPS]\n");
        return 2;
    }
    const drm::Mesh mesh = drm_test::readTinyPly(argv[1]);
    const std::vector<int32_t> grid = drm::quantize(mesh.positions, drm::makeGrid(mesh.positions, 12));
    const std::vector<uint8_t> file = drm::encode(mesh).bytes;
    if (argc == 5) {
        if (std::string(argv[3]) == "none") return 0;
        for (int r = 0; r < std::atoi(argv[4]); ++r) runOnce(argv[2], parseIndex(argv[3]), grid, file);
        return 0;
    }
    std::printf("| role | grid s | flann s | flann / grid |\n|---|---:|---:|---:|\n");
    for (const char* role : {"graph", "traversal"}) {
        double best[2] = {1e30, 1e30};
        for (int rep = 0; rep < 3; ++rep)  // interleaved, so that load changes hit both alike
            for (int k = 0; k < 2; ++k)
                best[k] = std::min(best[k], runOnce(role, k ? drm::NeighbourIndex::Flann : drm::NeighbourIndex::Grid,
                                                    grid, file));
        std::printf("| %s | %.3f | %.3f | %.2f |\n", role, best[0], best[1], best[1] / best[0]);
    }
    return 0;
}
