// drm-topology-study: prices the topological connectivity coder (codec/src/
// connectivity/topological/topological_coder.h) against the distance-ranked
// file, mesh by mesh, and shows where its bits go. A study tool: `drm
// encode --connectivity auto` makes the same comparison to choose a coder.
//
//   build/bin/drm-topology-study ../shared/meshes/*.ply
//
// For each mesh, at 12 bits: drm's default file (connectivity and geometry
// sections, bits per input vertex), the topological coder's two streams over
// the same manifold cut, and where its bits go by symbol.
#include <drmcodec/drmcodec.h>
#include <drm_vcg/mesh_io.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "mesh/manifold_cut.h"
#include "connectivity/topological/topological_coder.h"

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: drm-topology-study MESH.ply...\n");
        return 2;
    }
    std::printf("| mesh | V | drm conn | drm geo | topo conn | topo geo | drm total | topo total | new | end i | end j | other | boundary | symbol bits | rank bits |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    int failures = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string path = argv[i];
        try {
            const drm::Mesh mesh = drm::vcgio::loadMesh(path).mesh;
            const drm::Encoded encoded = drm::encode(mesh);
            const std::vector<int32_t> grid = drm::quantize(mesh.positions, drm::makeGrid(mesh.positions, 12));
            drm::ManifoldCut cut = drm::cutIntoManifold(mesh.triangles, mesh.vertexCount());
            std::vector<int32_t> cutGrid = grid;
            for (uint32_t original : cut.copyOf)
                cutGrid.insert(cutGrid.end(), grid.begin() + 3 * original, grid.begin() + 3 * original + 3);
            drm::TopologicalStats stats;
            const drm::TopologicalStreams streams = drm::encodeTopological(cutGrid, 12, cut.triangles, cut.copyOf, nullptr, &stats);
            const drm::TopologicalMesh back =
                drm::decodeTopological(streams.connectivity.data(), streams.connectivity.size(), streams.geometry.data(),
                                       streams.geometry.size(), mesh.vertexCount(), cut.copyOf.size(), cut.triangles.size() / 3, 12);
            if (back.triangles.size() != cut.triangles.size()) throw std::runtime_error("round trip lost faces");
            const double v = double(mesh.vertexCount());
            const drm::Stats& s = encoded.stats;
            const double edges = double(stats.symbols[0] + stats.symbols[1] + stats.symbols[2] + stats.symbols[3] + stats.symbols[4]);
            auto share = [&](int k) { return 100.0 * double(stats.symbols[k]) / edges; };
            std::string name = path.substr(path.find_last_of('/') + 1);
            std::printf("| %s | %zu | %.3f | %.2f | %.3f | %.2f | %.2f | %.2f | %.1f | %.1f | %.1f | %.1f | %.1f | %.3f | %.3f |\n", name.c_str(),
                        mesh.vertexCount(), 8.0 * double(s.connectivityBytes) / v, 8.0 * double(s.geometryBytes) / v,
                        8.0 * double(streams.connectivity.size()) / v, 8.0 * double(streams.geometry.size()) / v,
                        8.0 * double(s.totalBytes) / v, 8.0 * double(streams.connectivity.size() + streams.geometry.size()) / v,
                        share(1), share(2), share(3), share(4), share(0), stats.symbolBits / v, stats.rankBits / v);
            std::fflush(stdout);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: %s\n", path.c_str(), e.what());
            ++failures;
        }
    }
    return failures == 0 ? 0 : 1;
}
