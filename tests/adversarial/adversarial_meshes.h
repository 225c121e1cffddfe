// Small hand-made meshes that a manifold-only codec cannot take as they
// are (non-manifold edges and vertices, non-orientable or flipped faces,
// duplicated and degenerate faces, coincident vertices), and clean controls.
// Each says which repair its file must record.
#ifndef DRM_TEST_ADVERSARIAL_MESHES_H
#define DRM_TEST_ADVERSARIAL_MESHES_H

#include <drmcodec/drmcodec.h>

#include <string>
#include <vector>

namespace adversarial {

// What drm::Stats must report for a mesh.
enum class Repair {
    None,           // a clean mesh: every repair field 0, repairBytes 0
    SplitVertices,  // splitVertices >= 1 (a non-manifold edge or vertex)
    FlipFaces,      // flippedFaces >= 1 (faces against their neighbours)
    RepeatedFaces,  // repeatedFaces >= 1 (a face over an earlier face's vertices)
    LooseFaces,     // looseFaces >= 1 (faces repeating a vertex index)
    Some,           // some repair, the codec's choice which
};

struct AdversarialMesh {
    std::string name;  // letters, digits and '_' (a gtest name)
    drm::Mesh mesh;
    Repair repair;
};

// Built once, shared by every test that walks them.
const std::vector<AdversarialMesh>& adversarialMeshes();

}  // namespace adversarial

#endif  // DRM_TEST_ADVERSARIAL_MESHES_H
