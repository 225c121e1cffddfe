// The vcg mesh type the file readers load into.
//
// It carries every optional attribute vcglib's readers can fill (colours,
// normals, texture coordinates, quality, radius, edges), not because .drm
// keeps them but because a reader only reports an attribute in its load mask
// when the mesh type can hold it, and the tools warn about what is dropped.
#ifndef DRM_VCG_LOADING_MESH_H
#define DRM_VCG_LOADING_MESH_H

#include <vector>

#include <vcg/complex/complex.h>

namespace drm {
namespace vcgio {

class LoadingVertex;
class LoadingEdge;
class LoadingFace;
struct LoadingUsedTypes : public vcg::UsedTypes<vcg::Use<LoadingVertex>::AsVertexType,
                                                 vcg::Use<LoadingEdge>::AsEdgeType,
                                                 vcg::Use<LoadingFace>::AsFaceType> {};
class LoadingVertex
    : public vcg::Vertex<LoadingUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f,
                         vcg::vertex::Color4b, vcg::vertex::TexCoord2f, vcg::vertex::Qualityf,
                         vcg::vertex::Radiusf, vcg::vertex::BitFlags> {};
class LoadingEdge : public vcg::Edge<LoadingUsedTypes, vcg::edge::VertexRef, vcg::edge::BitFlags> {};
class LoadingFace
    : public vcg::Face<LoadingUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f,
                       vcg::face::Color4b, vcg::face::Qualityf, vcg::face::WedgeTexCoord2f,
                       vcg::face::BitFlags> {};
class LoadingMesh : public vcg::tri::TriMesh<std::vector<LoadingVertex>, std::vector<LoadingEdge>,
                                             std::vector<LoadingFace> > {};

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_LOADING_MESH_H
