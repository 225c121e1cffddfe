// Conversion between drm::Mesh and vcglib meshes.
//
// toVcg/fromVcg are templates over the vcg mesh type so that the MeshLab
// plugin can use them with MeshLab's CMeshO, and the tools with the small
// VcgMesh below (positions, face-face
// adjacency, flags). C++14-clean: included by MeshLab plugins.
#ifndef DRM_VCG_VCG_MESH_H
#define DRM_VCG_VCG_MESH_H

#include <drmcodec/drmcodec.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>

namespace drm {
namespace vcgio {

class VcgVertex;
class VcgFace;
struct VcgUsedTypes : public vcg::UsedTypes<vcg::Use<VcgVertex>::AsVertexType,
                                             vcg::Use<VcgFace>::AsFaceType> {};
class VcgVertex
    : public vcg::Vertex<VcgUsedTypes, vcg::vertex::Coord3f, vcg::vertex::BitFlags> {};
class VcgFace : public vcg::Face<VcgUsedTypes, vcg::face::VertexRef, vcg::face::FFAdj,
                                 vcg::face::BitFlags> {};
// The smallest vcg mesh on which vcg::tri::Clean's manifold counts run.
class VcgMesh : public vcg::tri::TriMesh<std::vector<VcgVertex>, std::vector<VcgFace> > {};

// Replaces the contents of `out` with `mesh`: vertex i and face f of `mesh`
// become out.vert[i] and out.face[f], corners in the same order.
// Throws drm::Error if a face refers to a vertex that does not exist.
template <class MeshType>
void toVcg(const drm::Mesh& mesh, MeshType& out) {
    typedef typename MeshType::ScalarType Scalar;
    if (mesh.positions.size() % 3 != 0 || mesh.triangles.size() % 3 != 0)
        throw drm::Error(drm::ErrorKind::InvalidInput, "mesh arrays are not a multiple of 3 long");
    const size_t vertexCount = mesh.vertexCount();
    const size_t faceCount = mesh.faceCount();
    for (size_t c = 0; c < mesh.triangles.size(); ++c) {
        if (mesh.triangles[c] >= vertexCount)
            throw drm::Error(drm::ErrorKind::InvalidInput, "face " + std::to_string(c / 3) + " refers to vertex " +
                             std::to_string(mesh.triangles[c]) + ", but the mesh has " +
                             std::to_string(vertexCount) + " vertices");
    }
    out.Clear();
    if (vertexCount > 0) vcg::tri::Allocator<MeshType>::AddVertices(out, vertexCount);
    for (size_t i = 0; i < vertexCount; ++i) {
        out.vert[i].P() = typename MeshType::CoordType(Scalar(mesh.positions[3 * i]),
                                                       Scalar(mesh.positions[3 * i + 1]),
                                                       Scalar(mesh.positions[3 * i + 2]));
    }
    // Faces after vertices: adding vertices may move them, adding faces does not.
    if (faceCount > 0) vcg::tri::Allocator<MeshType>::AddFaces(out, faceCount);
    for (size_t f = 0; f < faceCount; ++f) {
        for (int k = 0; k < 3; ++k) out.face[f].V(k) = &out.vert[mesh.triangles[3 * f + k]];
    }
}

// Index of vertex pointer `v` in `m.vert`, or SIZE_MAX when it points
// elsewhere (some vcglib readers store unchecked indices as pointers).
// Compared as addresses so that a stray pointer is detected, not followed.
template <class MeshType>
size_t vertexIndexOf(const MeshType& m, const typename MeshType::VertexType* v) {
    if (v == nullptr || m.vert.empty()) return std::numeric_limits<size_t>::max();
    const std::uintptr_t base = reinterpret_cast<std::uintptr_t>(m.vert.data());
    const std::uintptr_t p = reinterpret_cast<std::uintptr_t>(v);
    const std::uintptr_t stride = sizeof(typename MeshType::VertexType);
    if (p < base || p >= base + stride * m.vert.size() || (p - base) % stride != 0)
        return std::numeric_limits<size_t>::max();
    return size_t((p - base) / stride);
}

// The live part of a vcg mesh as a drm::Mesh. Deleted vertices and faces
// (MeshLab keeps them until the mesh is compacted) are left out; the others
// keep their relative order, so face f of the result is the f-th non-deleted
// face of `in`. Throws drm::Error if a face refers to a missing or deleted
// vertex, or is not a triangle.
template <class MeshType>
drm::Mesh fromVcg(const MeshType& in) {
    const uint32_t none = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> compactIndex(in.vert.size(), none);
    drm::Mesh out;
    out.positions.reserve(3 * in.vert.size());
    uint32_t liveVertices = 0;
    for (size_t i = 0; i < in.vert.size(); ++i) {
        if (in.vert[i].IsD()) continue;
        compactIndex[i] = liveVertices++;
        for (int k = 0; k < 3; ++k) out.positions.push_back(float(in.vert[i].cP()[k]));
    }
    out.triangles.reserve(3 * in.face.size());
    size_t liveFace = 0;
    for (size_t f = 0; f < in.face.size(); ++f) {
        const typename MeshType::FaceType& face = in.face[f];
        if (face.IsD()) continue;
        if (face.VN() != 3)
            throw drm::Error(drm::ErrorKind::InvalidInput, "face " + std::to_string(liveFace) + " has " +
                             std::to_string(face.VN()) + " corners, not 3");
        for (int k = 0; k < 3; ++k) {
            const size_t i = vertexIndexOf(in, face.cV(k));
            if (i == std::numeric_limits<size_t>::max() || compactIndex[i] == none)
                throw drm::Error(drm::ErrorKind::InvalidInput, "face " + std::to_string(liveFace) +
                                 " refers to a vertex that does not exist");
            out.triangles.push_back(compactIndex[i]);
        }
        ++liveFace;
    }
    return out;
}

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_VCG_MESH_H
