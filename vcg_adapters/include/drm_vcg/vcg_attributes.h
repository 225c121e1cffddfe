// Attributes between drm::Mesh and vcglib meshes: vertex colour, normal,
// texture coordinate and quality, face colour and quality, wedge (corner)
// texture coordinates with their texture index, and the texture list.
//
// Templates over the vcg mesh type, so that the file readers (LoadingMesh)
// and the MeshLab plugin (CMeshO, whose optional components must be enabled
// first) share one mapping. Which attributes are read is given as
// vcg::tri::io::Mask bits, the way vcglib's importers and MeshLab's export
// dialog say it. C++14-clean: included by MeshLab plugins.
#ifndef DRM_VCG_VCG_ATTRIBUTES_H
#define DRM_VCG_VCG_ATTRIBUTES_H

#include <drmcodec/drmcodec.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/io_mask.h>

namespace drm {
namespace vcgio {

// The vcg::tri::io::Mask bits for the attributes a drm::Mesh carries (the
// ones a vcg mesh can hold: corner normals are not among them).
inline int ioMaskOf(const drm::Mesh& mesh) {
    typedef vcg::tri::io::Mask M;
    int mask = 0;
    if (!mesh.colors.empty()) mask |= M::IOM_VERTCOLOR;
    if (!mesh.normals.empty()) mask |= M::IOM_VERTNORMAL;
    if (!mesh.texCoords.empty()) mask |= M::IOM_VERTTEXCOORD;
    if (!mesh.quality.empty()) mask |= M::IOM_VERTQUALITY;
    if (!mesh.cornerTexCoords.empty()) mask |= M::IOM_WEDGTEXCOORD;
    if (!mesh.faceTexture.empty()) mask |= M::IOM_WEDGTEXMULTI;
    if (!mesh.faceColors.empty()) mask |= M::IOM_FACECOLOR;
    if (!mesh.faceQuality.empty()) mask |= M::IOM_FACEQUALITY;
    return mask;
}

// Fills `out`'s attribute arrays from `in` for the attributes in `mask`
// (vcg::tri::io::Mask bits) that `in` can hold, and the texture list when
// texture coordinates are read. Like fromVcg, deleted vertices and faces are
// left out, so entry i follows fromVcg's vertex i and face i. Textures with
// more than one image get faceTexture (the first wedge's index; a negative
// index, MeshLab's "no texture", becomes 0).
template <class MeshType>
void attributesFromVcg(const MeshType& in, int mask, drm::Mesh& out) {
    typedef vcg::tri::io::Mask M;
    std::vector<const typename MeshType::VertexType*> vertices;
    vertices.reserve(in.vert.size());
    for (size_t i = 0; i < in.vert.size(); ++i)
        if (!in.vert[i].IsD()) vertices.push_back(&in.vert[i]);
    std::vector<const typename MeshType::FaceType*> faces;
    faces.reserve(in.face.size());
    for (size_t f = 0; f < in.face.size(); ++f)
        if (!in.face[f].IsD()) faces.push_back(&in.face[f]);

    if ((mask & M::IOM_VERTCOLOR) && vcg::tri::HasPerVertexColor(in)) {
        out.colors.resize(4 * vertices.size());
        for (size_t i = 0; i < vertices.size(); ++i)
            for (int k = 0; k < 4; ++k) out.colors[4 * i + size_t(k)] = uint8_t(vertices[i]->cC()[k]);
    }
    if ((mask & M::IOM_VERTNORMAL) && vcg::tri::HasPerVertexNormal(in)) {
        out.normals.resize(3 * vertices.size());
        for (size_t i = 0; i < vertices.size(); ++i)
            for (int k = 0; k < 3; ++k) out.normals[3 * i + size_t(k)] = float(vertices[i]->cN()[k]);
    }
    if ((mask & M::IOM_VERTTEXCOORD) && vcg::tri::HasPerVertexTexCoord(in)) {
        out.texCoords.resize(2 * vertices.size());
        for (size_t i = 0; i < vertices.size(); ++i) {
            out.texCoords[2 * i] = float(vertices[i]->cT().U());
            out.texCoords[2 * i + 1] = float(vertices[i]->cT().V());
        }
    }
    if ((mask & M::IOM_VERTQUALITY) && vcg::tri::HasPerVertexQuality(in)) {
        out.quality.resize(vertices.size());
        for (size_t i = 0; i < vertices.size(); ++i) out.quality[i] = float(vertices[i]->cQ());
    }
    if ((mask & M::IOM_FACECOLOR) && vcg::tri::HasPerFaceColor(in)) {
        out.faceColors.resize(4 * faces.size());
        for (size_t f = 0; f < faces.size(); ++f)
            for (int k = 0; k < 4; ++k) out.faceColors[4 * f + size_t(k)] = uint8_t(faces[f]->cC()[k]);
    }
    if ((mask & M::IOM_FACEQUALITY) && vcg::tri::HasPerFaceQuality(in)) {
        out.faceQuality.resize(faces.size());
        for (size_t f = 0; f < faces.size(); ++f) out.faceQuality[f] = float(faces[f]->cQ());
    }
    const bool wedges = (mask & M::IOM_WEDGTEXCOORD) && vcg::tri::HasPerWedgeTexCoord(in);
    if (wedges) {
        out.cornerTexCoords.resize(6 * faces.size());
        for (size_t f = 0; f < faces.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                out.cornerTexCoords[6 * f + 2 * size_t(k)] = float(faces[f]->cWT(k).U());
                out.cornerTexCoords[6 * f + 2 * size_t(k) + 1] = float(faces[f]->cWT(k).V());
            }
        if (in.textures.size() > 1) {
            out.faceTexture.resize(faces.size());
            for (size_t f = 0; f < faces.size(); ++f) {
                const int n = faces[f]->cWT(0).N();
                out.faceTexture[f] = n < 0 ? 0u : uint32_t(n);
            }
        }
    }
    if (wedges || !out.texCoords.empty()) out.textures.assign(in.textures.begin(), in.textures.end());
}

// Writes `mesh`'s attributes into `m`, which holds toVcg(mesh) (same vertex
// and face order). Only components `m` has (or has enabled) are written;
// returns the vcg::tri::io::Mask bits of those written. Corner normals,
// which vcg meshes do not hold per wedge, become per-vertex normals (the
// normalized sum of each vertex's corner normals) when the mesh has no
// per-vertex normals.
template <class MeshType>
int attributesToVcg(const drm::Mesh& mesh, MeshType& m) {
    typedef vcg::tri::io::Mask M;
    typedef typename MeshType::ScalarType Scalar;
    int written = 0;
    const size_t vn = mesh.vertexCount(), fn = mesh.faceCount();
    if (m.vert.size() != vn || m.face.size() != fn) return 0;
    if (mesh.colors.size() == 4 * vn && vn > 0 && vcg::tri::HasPerVertexColor(m)) {
        for (size_t i = 0; i < vn; ++i)
            m.vert[i].C() = vcg::Color4b(mesh.colors[4 * i], mesh.colors[4 * i + 1], mesh.colors[4 * i + 2],
                                         mesh.colors[4 * i + 3]);
        written |= M::IOM_VERTCOLOR;
    }
    if (vn > 0 && vcg::tri::HasPerVertexNormal(m)) {
        if (mesh.normals.size() == 3 * vn) {
            for (size_t i = 0; i < vn; ++i)
                m.vert[i].N() = typename MeshType::VertexType::NormalType(
                    Scalar(mesh.normals[3 * i]), Scalar(mesh.normals[3 * i + 1]), Scalar(mesh.normals[3 * i + 2]));
            written |= M::IOM_VERTNORMAL;
        } else if (mesh.cornerNormals.size() == 9 * fn) {
            for (size_t i = 0; i < vn; ++i) m.vert[i].N().SetZero();
            for (size_t c = 0; c < 3 * fn; ++c) {
                typename MeshType::VertexType& v = m.vert[mesh.triangles[c]];
                for (int k = 0; k < 3; ++k) v.N()[k] += Scalar(mesh.cornerNormals[3 * c + size_t(k)]);
            }
            for (size_t i = 0; i < vn; ++i)
                if (m.vert[i].N().Norm() > 0) m.vert[i].N().Normalize();
            written |= M::IOM_VERTNORMAL;
        }
    }
    if (mesh.texCoords.size() == 2 * vn && vn > 0 && vcg::tri::HasPerVertexTexCoord(m)) {
        for (size_t i = 0; i < vn; ++i) {
            m.vert[i].T().U() = mesh.texCoords[2 * i];
            m.vert[i].T().V() = mesh.texCoords[2 * i + 1];
            m.vert[i].T().N() = 0;
        }
        written |= M::IOM_VERTTEXCOORD;
    }
    if (mesh.quality.size() == vn && vn > 0 && vcg::tri::HasPerVertexQuality(m)) {
        for (size_t i = 0; i < vn; ++i) m.vert[i].Q() = mesh.quality[i];
        written |= M::IOM_VERTQUALITY;
    }
    if (mesh.faceColors.size() == 4 * fn && fn > 0 && vcg::tri::HasPerFaceColor(m)) {
        for (size_t f = 0; f < fn; ++f)
            m.face[f].C() = vcg::Color4b(mesh.faceColors[4 * f], mesh.faceColors[4 * f + 1],
                                         mesh.faceColors[4 * f + 2], mesh.faceColors[4 * f + 3]);
        written |= M::IOM_FACECOLOR;
    }
    if (mesh.faceQuality.size() == fn && fn > 0 && vcg::tri::HasPerFaceQuality(m)) {
        for (size_t f = 0; f < fn; ++f) m.face[f].Q() = mesh.faceQuality[f];
        written |= M::IOM_FACEQUALITY;
    }
    if (mesh.cornerTexCoords.size() == 6 * fn && fn > 0 && vcg::tri::HasPerWedgeTexCoord(m)) {
        const bool indexed = mesh.faceTexture.size() == fn;
        for (size_t f = 0; f < fn; ++f)
            for (int k = 0; k < 3; ++k) {
                m.face[f].WT(k).U() = mesh.cornerTexCoords[6 * f + 2 * size_t(k)];
                m.face[f].WT(k).V() = mesh.cornerTexCoords[6 * f + 2 * size_t(k) + 1];
                m.face[f].WT(k).N() = short(indexed ? mesh.faceTexture[f] : 0u);
            }
        written |= M::IOM_WEDGTEXCOORD;
        if (indexed) written |= M::IOM_WEDGTEXMULTI;
    }
    m.textures.assign(mesh.textures.begin(), mesh.textures.end());
    return written;
}

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_VCG_ATTRIBUTES_H
