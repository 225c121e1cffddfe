// The .drm container: signature, version, then three sections (header,
// connectivity, geometry) and optional ones (vertex order, repairs,
// attributes), each with its length and CRC-32. docs/format.md is the
// byte-level specification; keep the two in step.
#ifndef DRM_FILE_FORMAT_H
#define DRM_FILE_FORMAT_H

#include <cstdint>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"

namespace drm {

constexpr uint8_t kSignature[8] = {0x89, 'D', 'R', 'M', '\r', '\n', 0x1A, '\n'};
// The one version written and read. Files of earlier (pre-release)
// versions are refused with a message naming their version.
constexpr uint16_t kFormatVersion = kFileFormatVersion;

constexpr uint16_t kFlagCurvature = 1;
constexpr uint16_t kFlagTopologicalFilter = 2;
constexpr uint16_t kFlagGapClosing = 4;
constexpr uint16_t kFlagConfidenceContext = 8;
constexpr uint16_t kFlagAngleOrder = 16;
constexpr uint16_t kFlagVertexOrder = 32;  // a fourth section holds the input vertex order
constexpr uint16_t kFlagRepairs = 64;      // a repairs section undoes a manifold cut (repair_section.h)
constexpr uint16_t kFlagAttributes = 128;  // attribute sections follow (attribute_sections.h)
constexpr uint16_t kFlagFrontNeighbours = 256;
// The connectivity numbers the vertices in the vertex section's order
// instead of Morton order (morton_order.h).
constexpr uint16_t kFlagSectionNumbering = 512;
constexpr uint16_t kFlagBoundaryFlag = 1024;  // the boundary flag lever (Levers::boundaryFlag)
// The connectivity section holds two parts, decodable apart (connectivity_parts.h).
constexpr uint16_t kFlagTwoParts = 2048;
constexpr uint16_t kKnownFlags = 4095;
constexpr uint64_t kMaxAttributeSections = 32;

struct FileHeader {
    uint64_t vertexCount = 0;
    uint64_t faceCount = 0;
    Grid grid;
    Predictor predictor = Predictor::Midpoint;
    bool curvature = false;
    bool keepsVertexOrder = false;
    // The connectivity's vertices in Morton order of their grid points
    // (morton_order.h), or else in the vertex section's order
    // (kFlagSectionNumbering).
    bool mortonNumbering = true;
    // The connectivity section holds two parts
    // (kFlagTwoParts, connectivity_parts.h).
    bool twoParts = false;
    Levers levers;
    ConnectivityCoder connectivityCoder = ConnectivityCoder::Ranks;
    GeometryCoder geometryCoder = GeometryCoder::SpanningTree;
    // With repairs: vertices vertexCount .. vertexCount + copyCount - 1 of
    // the traversal are copies (listed in the repairs section).
    bool hasRepairs = false;
    uint64_t copyCount = 0;
    // With attributes: how many attribute sections follow the others.
    uint64_t attributeSections = 0;
    // Edge-connected components the traversal codes (their start triangles
    // are in the connectivity section, start_triangle.h).
    uint64_t componentCount = 0;
};

struct FileParts {
    int formatVersion = 0;  // as read: kFormatVersion
    FileHeader header;
    const uint8_t* connectivity = nullptr;
    size_t connectivitySize = 0;
    const uint8_t* geometry = nullptr;
    size_t geometrySize = 0;
    const uint8_t* vertexOrder = nullptr;  // when header.keepsVertexOrder
    size_t vertexOrderSize = 0;
    const uint8_t* repairs = nullptr;  // when header.hasRepairs
    size_t repairsSize = 0;
    struct Payload {
        const uint8_t* data;
        size_t size;
    };
    std::vector<Payload> attributes;  // header.attributeSections of them
    size_t attributeBytes = 0;        // the attribute sections, framing included
    size_t headerBytes = 0;  // everything but the payloads
};

constexpr uint64_t kMaxVertexCount = 0xFFFFFFFEull;  // indices are uint32, one value kept for "none"
constexpr uint64_t kMaxFaceCount = 0x55555554ull;    // 3 * faces corners fit in uint32

// What is wrong with a header, or "": the checks the reader makes on every
// field, which writeFile makes before it writes anything.
std::string headerProblem(const FileHeader& header);

// vertexOrder is written iff header.keepsVertexOrder, then repairs iff
// header.hasRepairs, then the attribute sections (their count and flag are
// set from the list, whatever header says). *written, if given, gets the
// file's header and section table as readFile would give them (sizes
// only; the payload pointers are left null), for fillStatsFromHeader.
std::vector<uint8_t> writeFile(const FileHeader& header, const std::vector<uint8_t>& connectivity,
                               const std::vector<uint8_t>& geometry, const std::vector<uint8_t>& vertexOrder,
                               const std::vector<uint8_t>& repairs,
                               const std::vector<std::vector<uint8_t>>& attributes, FileParts* written);

// Checks signature, version, section lengths and checksums, and every header
// field's range; the payloads are returned as pointers into data.
FileParts readFile(const uint8_t* data, size_t size);

}  // namespace drm

#endif  // DRM_FILE_FORMAT_H
