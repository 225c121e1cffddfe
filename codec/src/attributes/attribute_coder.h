// One attribute section: integer values (already quantized) per vertex,
// per corner or per face of the decoded mesh, predicted from the decoded
// mesh (positions, connectivity, values decoded so far) and range coded.
//
// Per-corner values are grouped into wedges: the corners around a vertex
// that an interior edge joins without a seam share one value. The section
// codes a seam bit per interior edge, then one value per wedge, wedges in
// the order of their first corner (the traversal's face order), then, for
// per-vertex layouts, the vertices no face uses. The encoder tries every
// predictor the attribute allows and keeps the smallest section.
// docs/format.md, "Attribute sections (flag bit 7)", is the byte-level
// description.
#ifndef DRM_ATTRIBUTE_CODER_H
#define DRM_ATTRIBUTE_CODER_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "attributes/corner_table.h"

namespace drm {

enum class AttributeSemantic : uint8_t {
    Color = 1,     // 3 or 4 components of 8 bits
    Normal = 2,    // 2 octahedral components of normalBits
    TexCoord = 3,  // 2 components of uvBits over a square grid
    Quality = 4,   // 1 component: the float's bits, ordered as integers
    Material = 5,  // 1 component: a face's index into the material names
    Texture = 6,   // 1 component: a face's index into the texture names
};

enum class AttributeLayout : uint8_t {
    Vertex = 0,        // one value per vertex
    Corner = 1,        // one value per corner (wedges)
    Face = 2,          // one value per face
    WeldedVertex = 3,  // an input's per-vertex values after welding: coded per corner; the decoder
                       // gives each distinct (vertex, values) its own vertex again
};

enum class AttributePredictor : uint8_t {
    Previous = 0,       // the value coded before
    RingAverage = 1,    // mean of the decoded values at the wedge's neighbouring corners
    Parallelogram = 2,  // mean of a + b - o over the decoded triangles across the wedge's faces
    GeometricNormal = 3,  // the area-weighted normal of the wedge's faces (normals)
    GeometricUv = 4,      // the triangle's shape carried into texture space (texture coordinates)
    AdjacentFace = 5,     // the value of the first earlier face across an edge (per-face layout)
    FaceOrGeometricNormal = 6,  // a decoded corner of the same face, else the geometric normal
                                // (flat-shaded meshes: every face's corners share its normal)
};

// The values of one attribute and how they are quantized.
struct AttributeValues {
    AttributeSemantic semantic = AttributeSemantic::Color;
    AttributeLayout layout = AttributeLayout::Vertex;
    int components = 1;
    int bits = 8;                  // per component: values lie in [0, 2^bits)
    std::vector<uint32_t> values;  // components per element (vertex, corner or face)
    // Normals only: elements whose normal is zero (their values are 0);
    // empty when none is.
    std::vector<uint8_t> zero;
    // Texture coordinates: u = uvOrigin[0] + value * uvStep.
    double uvOrigin[2] = {0, 0};
    double uvStep = 1;

    size_t elementCount() const { return components > 0 ? values.size() / size_t(components) : 0; }
};

// The decoded mesh the predictions use.
struct AttributeMesh {
    const std::vector<uint32_t>& triangles;
    const std::vector<int32_t>& grid;  // 3 per vertex
    size_t vertexCount;
    const CornerTable& corners;
};

// The section payload (semantic, layout and parameters included).
std::vector<uint8_t> encodeAttribute(const AttributeValues& attribute, const AttributeMesh& mesh);

// Whether decoding this payload needs the corner table's opposites (seams,
// parallelograms, adjacent faces); false for a payload too short to say.
bool attributeNeedsOpposites(const uint8_t* data, size_t size);

// Throws Error("corrupt file: ...") on a payload that does not decode to
// exactly one value per element.
AttributeValues decodeAttribute(const uint8_t* data, size_t size, const AttributeMesh& mesh);

// The wedges of corner layouts: wedgeOf[c] for every corner, wedges
// numbered by their first corner. For per-vertex layouts every corner of a
// vertex is one wedge. seam[e] per CornerTable::interiorEdges entry.
std::vector<uint32_t> wedgesOf(const AttributeMesh& mesh, const std::vector<uint8_t>& seam, bool perVertex,
                               uint32_t* wedgeCount);

}  // namespace drm

#endif  // DRM_ATTRIBUTE_CODER_H
