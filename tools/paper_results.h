// Published connectivity rates of the distance-ranked coder, for `drm bench`.
#ifndef DRM_TOOLS_PAPER_RESULTS_H
#define DRM_TOOLS_PAPER_RESULTS_H

#include <string>

namespace drm {
namespace cli {

// Connectivity bits per vertex of the paper's distance-ranked (DR) coder,
// Table 4 of Marais, Gain and Shreiner, for the models of which
// ../shared/meshes holds the exact mesh (matched by file stem, exactly).
// Returns false for any other mesh.
inline bool paperConnectivityBitsPerVertex(const std::string& stem, double& bitsPerVertex) {
    static const struct { const char* stem; double bpv; } table[] = {
        {"bunny", 0.59}, {"fandisk", 0.65}, {"feline", 1.95},    {"horse", 0.70},
        {"horse-lres", 0.44}, {"nefertiti", 1.66}, {"venus", 1.79}, {"venus-lres", 2.30},
    };
    for (const auto& entry : table) {
        if (stem == entry.stem) {
            bitsPerVertex = entry.bpv;
            return true;
        }
    }
    return false;
}

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_PAPER_RESULTS_H
