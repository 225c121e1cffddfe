// A mesh's attributes as .drm sections: checked and quantized from the
// input's arrays, put in the decoded mesh's order, coded (attribute_coder.h)
// and, on decoding, turned back into drm::Mesh arrays. Also the welding of
// meshes exported with a vertex per corner, and the split that gives each
// distinct (vertex, values) of a welded mesh its own vertex again.
#ifndef DRM_ATTRIBUTE_SECTIONS_H
#define DRM_ATTRIBUTE_SECTIONS_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "container/file_format.h"

namespace drm {

// Throws Error naming the array or element at fault: wrong sizes, NaN or
// infinite normals, texture coordinates or a texture grid that would not
// decode to finite floats; options out of range.
void checkAttributes(const Mesh& mesh, const EncodeOptions& options);

// Welding: every vertex that faces use, merged with the others on its grid
// point (first occurrence represents them); vertices no face uses stay.
struct Welding {
    std::vector<uint32_t> weldedOf;        // input vertex -> welded vertex
    std::vector<uint32_t> representative;  // welded vertex -> input vertex
    Mesh mesh;                             // positions and triangles over welded vertices
    size_t merged() const { return weldedOf.size() - representative.size(); }
};
bool shouldWeld(const Mesh& mesh, const std::vector<int32_t>& quantized, const EncodeOptions& options);
Welding weld(const Mesh& mesh, const std::vector<int32_t>& quantized);

// The decoded mesh as the encoder knows it: faces and vertices of the core
// file, with where each came from in the input.
struct DecodedLayout {
    const std::vector<uint32_t>& triangles;   // decoded faces, decoded vertex indices
    const std::vector<int32_t>& grid;          // decoded vertices' grid points, 3 each
    std::vector<uint32_t> vertexInput;         // decoded vertex -> input vertex (representative if welded)
    std::vector<uint32_t> faceInput;           // decoded face -> input face
    std::vector<uint8_t> faceRotation;         // decoded corner k is input corner (k + rotation) % 3
    bool welded = false;
};

struct AttributeEncoding {
    std::vector<std::vector<uint8_t>> sections;
    std::vector<Stats::AttributeSize> sizes;
    // With welding: decoded vertex (after the split) -> input vertex, and
    // the decoded faces over the split vertices.
    std::vector<uint32_t> splitVertexInput;
    std::vector<uint32_t> splitTriangles;
};
AttributeEncoding encodeAttributeSections(const Mesh& input, const EncodeOptions& options, const DecodedLayout& layout);

// Fills result.mesh's attribute arrays from the sections (result.mesh's
// triangles and result.quantized are the core's), splitting welded
// vertices; fills result.stats.attributeSizes.
void decodeAttributeSections(const FileParts& parts, Decoded& result);

// The name an attribute section is listed under in Stats::attributeSizes
// ("normals", "materials", ...), read from its first bytes without decoding
// it; throws Error on a section decode would refuse by its kind.
std::string attributeSectionName(const uint8_t* data, size_t size);

}  // namespace drm

#endif  // DRM_ATTRIBUTE_SECTIONS_H
