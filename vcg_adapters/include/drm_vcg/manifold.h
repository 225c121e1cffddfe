// A friendly manifold check, run by the tools before encoding.
//
// The codec refuses non-manifold or inconsistently oriented meshes itself;
// this check counts every problem (with vcg::tri::Clean) so the user hears
// how much is wrong, not only the first element the codec trips over.
// C++14-clean.
#ifndef DRM_VCG_MANIFOLD_H
#define DRM_VCG_MANIFOLD_H

#include <drm/drm.h>

#include <cstddef>
#include <string>

namespace drm {
namespace vcgio {

struct ManifoldReport {
    size_t facesRepeatingVertex = 0;  // faces using one vertex twice
    size_t nonManifoldEdges = 0;      // edges with more than two faces
    // Vertices whose faces form more than one fan (vertices on non-manifold
    // edges are not counted again).
    size_t nonManifoldVertices = 0;
    // Edges whose two faces traverse them in the same direction; counted
    // only when there are no non-manifold edges.
    size_t misorientedEdges = 0;
    // One sentence naming the first problem found (vertex and face indices
    // are the mesh's, 0-based), or empty.
    std::string firstProblem;

    bool ok() const {
        return facesRepeatingVertex == 0 && nonManifoldEdges == 0 && nonManifoldVertices == 0 &&
               misorientedEdges == 0;
    }
    // e.g. "2 non-manifold edges, 1 non-manifold vertex; first: edge (3, 7) ..."
    std::string summary() const;
};

// Throws drm::Error if a face refers to a vertex that does not exist.
ManifoldReport checkManifold(const drm::Mesh& mesh);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_MANIFOLD_H
