// What drm-peer-bench prints and writes: per-mesh tables of connectivity and
// total bits per vertex and of encode and decode times, drm's ratios to the
// peers, and notes on refusals and decoded counts that differ from the input.
#ifndef DRM_TOOLS_BENCH_REPORT_H
#define DRM_TOOLS_BENCH_REPORT_H

#include "measure.h"

#include <string>
#include <vector>

namespace drm {
namespace peers {

struct MeshResult {
    std::string name;                 // file name
    bool read = false;                // false: readError says why
    std::string readError;
    uint64_t vertices = 0;            // of the input: every bpv figure divides by this
    uint64_t triangles = 0;
    bool hasPaper = false;            // one of the paper's models (Table 4)
    double paperBpv = 0;
    std::vector<Measurement> codecs;  // in BenchRun::codecs order
};

struct BenchRun {
    int bits = 12;
    int runs = 3;
    std::vector<std::string> codecs;        // Peer::name()
    std::vector<std::string> descriptions;  // Peer::description()
    std::vector<MeshResult> meshes;
    std::string command;                    // the command line, quoted in the Markdown
};

std::string textReport(const BenchRun& run);
// A whole document (docs/peers.md): setup, summary, tables, notes.
std::string markdownReport(const BenchRun& run);
// One row per mesh and codec.
std::string csvReport(const BenchRun& run);

}  // namespace peers
}  // namespace drm

#endif  // DRM_TOOLS_BENCH_REPORT_H
