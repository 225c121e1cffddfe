#include "container/file_format.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "connectivity/connectivity_coders.h"
#include "container/byte_io.h"
#include "container/crc32.h"
#include "geometry/geometry_coders.h"
#include "mesh/quantize.h"

namespace drm {
namespace {

// A section's checksum covers the format version (its two bytes as
// stored) before the payload: a file whose version field is changed fails
// its checksums as well as the version check.
uint32_t sectionChecksum(const uint8_t* payload, size_t size) {
    const uint8_t stored[2] = {uint8_t(kFormatVersion & 0xFF), uint8_t(kFormatVersion >> 8)};
    return crc32(payload, size, crc32(stored, 2));
}

void writeSection(ByteWriter& out, const std::vector<uint8_t>& payload) {
    out.varint(payload.size());
    out.u32(sectionChecksum(payload.data(), payload.size()));
    out.bytes(payload);
}

std::vector<uint8_t> encodeHeader(const FileHeader& h) {
    ByteWriter out;
    out.u16(uint16_t((h.curvature ? kFlagCurvature : 0) | (h.levers.topologicalFilter ? kFlagTopologicalFilter : 0) |
                     (h.levers.gapClosing ? kFlagGapClosing : 0) |
                     (h.levers.confidenceContext ? kFlagConfidenceContext : 0) |
                     (h.levers.angleOrder ? kFlagAngleOrder : 0) | (h.keepsVertexOrder ? kFlagVertexOrder : 0) |
                     (h.hasRepairs ? kFlagRepairs : 0) | (h.attributeSections > 0 ? kFlagAttributes : 0) |
                     (h.levers.frontNeighbours ? kFlagFrontNeighbours : 0) |
                     (h.levers.boundaryFlag ? kFlagBoundaryFlag : 0) |
                     (h.mortonNumbering ? 0 : kFlagSectionNumbering) | (h.twoParts ? kFlagTwoParts : 0)));
    out.u8(uint8_t(h.grid.bits));
    out.u8(uint8_t(h.predictor));
    out.u8(uint8_t(h.connectivityCoder));
    out.u8(uint8_t(h.geometryCoder));
    for (double o : h.grid.origin) out.f64(o);
    out.f64(h.grid.step);
    out.varint(h.vertexCount);
    out.varint(h.faceCount);
    if (h.hasRepairs) out.varint(h.copyCount);
    if (h.attributeSections > 0) out.varint(h.attributeSections);
    out.varint(h.componentCount);  // the start triangles are in the connectivity section
    return std::move(out.buffer());
}

FileHeader decodeHeader(ByteReader& in) {
    FileHeader h;
    const uint16_t flags = in.u16("flags");
    if (flags & ~kKnownFlags) throw Error(ErrorKind::Corrupt, "corrupt file: unknown header flags " + std::to_string(flags));
    h.curvature = (flags & kFlagCurvature) != 0;
    h.levers.topologicalFilter = (flags & kFlagTopologicalFilter) != 0;
    h.levers.gapClosing = (flags & kFlagGapClosing) != 0;
    h.levers.confidenceContext = (flags & kFlagConfidenceContext) != 0;
    h.levers.angleOrder = (flags & kFlagAngleOrder) != 0;
    h.levers.frontNeighbours = (flags & kFlagFrontNeighbours) != 0;
    h.levers.boundaryFlag = (flags & kFlagBoundaryFlag) != 0;
    h.keepsVertexOrder = (flags & kFlagVertexOrder) != 0;
    h.hasRepairs = (flags & kFlagRepairs) != 0;
    h.mortonNumbering = !(flags & kFlagSectionNumbering);
    h.twoParts = (flags & kFlagTwoParts) != 0;
    h.grid.bits = in.u8("quantization bits");
    if (h.grid.bits < kMinBits || h.grid.bits > kMaxBits)
        throw Error(ErrorKind::Corrupt, "corrupt file: quantization bits " + std::to_string(h.grid.bits) + " out of range " +
                    std::to_string(kMinBits) + ".." + std::to_string(kMaxBits));
    const uint8_t predictor = in.u8("predictor");
    if (predictor != uint8_t(Predictor::Parallelogram) && predictor != uint8_t(Predictor::Midpoint))
        throw Error(ErrorKind::Corrupt, "corrupt file: unknown predictor " + std::to_string(predictor));
    h.predictor = Predictor(predictor);
    const uint8_t connectivity = in.u8("connectivity coder");
    const ConnectivityCoderEntry* connectivityCoder = connectivityCoderById(connectivity);
    if (!connectivityCoder)
        throw Error(ErrorKind::Unsupported, "unsupported file: unknown connectivity coder " + std::to_string(connectivity));
    h.connectivityCoder = connectivityCoder->id;
    if (h.twoParts && !connectivityCoder->splitsInTwoParts)
        throw Error(ErrorKind::Corrupt, std::string("corrupt file: a ") + connectivityCoder->name +
                    " connectivity section in two parts");
    const uint8_t geometry = in.u8("geometry coder");
    if (!geometryCoderById(geometry))
        throw Error(ErrorKind::Unsupported, "unsupported file: unknown geometry coder " + std::to_string(geometry));
    h.geometryCoder = GeometryCoder(geometry);
    for (double& o : h.grid.origin) o = in.f64("bounding box origin");
    h.grid.step = in.f64("grid step");
    // Decoded coordinates are checked one by one as they are made: a box
    // as wide as float's range holds (-2e38 .. 2e38 has an extent of 4e38),
    // and only a grid point past FLT_MAX is refused.
    const std::string gridFault = gridProblem(h.grid);
    if (!gridFault.empty()) throw Error(ErrorKind::Corrupt, "corrupt file: " + gridFault);
    h.vertexCount = in.count("vertex count", kMaxVertexCount);
    if (h.vertexCount == 0) throw Error(ErrorKind::Corrupt, "corrupt file: the vertex count is zero");
    h.faceCount = in.count("face count", kMaxFaceCount);
    // A cut makes at most one copy per face corner.
    if (h.hasRepairs)
        h.copyCount = in.count("vertex copy count", std::min<uint64_t>(3 * h.faceCount, kMaxVertexCount - h.vertexCount));
    if (flags & kFlagAttributes) {
        h.attributeSections = in.count("attribute section count", kMaxAttributeSections);
        if (h.attributeSections == 0) throw Error(ErrorKind::Corrupt, "corrupt file: the attribute flag is set with no attribute section");
    }
    // Nothing is allocated by the count: the decoder checks each component
    // against the faces it has left.
    h.componentCount = in.count("component count", h.faceCount);
    if (in.remaining() != 0)
        throw Error(ErrorKind::Corrupt, "corrupt file: " + std::to_string(in.remaining()) + " unexpected bytes at the end of the header");
    const std::string problem = headerProblem(h);
    if (!problem.empty()) throw Error(ErrorKind::Corrupt, "corrupt file: the header holds " + problem);
    return h;
}

}  // namespace

std::string headerProblem(const FileHeader& h) {
    const std::string grid = gridProblem(h.grid);
    if (!grid.empty()) return grid;
    if (h.predictor != Predictor::Parallelogram && h.predictor != Predictor::Midpoint)
        return "unknown predictor " + std::to_string(int(h.predictor));
    if (!geometryCoderOf(h.geometryCoder))
        return "unknown geometry coder " + std::to_string(int(h.geometryCoder));
    if (h.connectivityCoder != ConnectivityCoder::Ranks && h.connectivityCoder != ConnectivityCoder::Topological)
        return "unknown connectivity coder " + std::to_string(int(h.connectivityCoder));
    if (h.connectivityCoder == ConnectivityCoder::Topological && h.twoParts) return "a topological connectivity in two parts";
    if (h.vertexCount == 0 || h.vertexCount > kMaxVertexCount)
        return std::to_string(h.vertexCount) + " vertices (a file holds 1 to " + std::to_string(kMaxVertexCount) + ")";
    if (h.faceCount > kMaxFaceCount)
        return std::to_string(h.faceCount) + " faces (a file holds at most " + std::to_string(kMaxFaceCount) + ")";
    if (h.copyCount > std::min<uint64_t>(3 * h.faceCount, kMaxVertexCount - h.vertexCount) ||
        (!h.hasRepairs && h.copyCount != 0))
        return std::to_string(h.copyCount) + " vertex copies for " + std::to_string(h.vertexCount) + " vertices and " +
               std::to_string(h.faceCount) + " faces";
    if (h.attributeSections > kMaxAttributeSections)
        return std::to_string(h.attributeSections) + " attribute sections (at most " +
               std::to_string(kMaxAttributeSections) + ")";
    if (h.componentCount > h.faceCount) return "more components than faces";
    return "";
}

std::vector<uint8_t> writeFile(const FileHeader& header, const std::vector<uint8_t>& connectivity,
                               const std::vector<uint8_t>& geometry, const std::vector<uint8_t>& vertexOrder,
                               const std::vector<uint8_t>& repairs,
                               const std::vector<std::vector<uint8_t>>& attributes, FileParts* written) {
    FileHeader withCount = header;
    withCount.attributeSections = attributes.size();
    // Never a file the reader refuses: the reader's own test of the header.
    const std::string problem = headerProblem(withCount);
    if (!problem.empty()) throw Error(ErrorKind::InvalidInput, "cannot encode this mesh: the file would hold " + problem);
    ByteWriter out;
    out.bytes(kSignature, sizeof kSignature);
    out.u16(kFormatVersion);
    writeSection(out, encodeHeader(withCount));
    writeSection(out, connectivity);
    writeSection(out, geometry);
    if (header.keepsVertexOrder) writeSection(out, vertexOrder);
    if (header.hasRepairs) writeSection(out, repairs);
    const size_t beforeAttributes = out.size();
    for (const std::vector<uint8_t>& a : attributes) writeSection(out, a);
    if (written) {
        // The sizes readFile finds in this file (payloads without framing).
        FileParts& parts = *written;
        parts = FileParts();
        parts.formatVersion = kFormatVersion;
        parts.connectivitySize = connectivity.size();
        parts.geometrySize = geometry.size();
        parts.vertexOrderSize = header.keepsVertexOrder ? vertexOrder.size() : 0;
        parts.repairsSize = header.hasRepairs ? repairs.size() : 0;
        for (const std::vector<uint8_t>& a : attributes) parts.attributes.push_back({nullptr, a.size()});
        parts.attributeBytes = out.size() - beforeAttributes;
        parts.headerBytes = out.size() - parts.connectivitySize - parts.geometrySize - parts.vertexOrderSize -
                            parts.repairsSize - parts.attributeBytes;
        parts.header = std::move(withCount);
    }
    return std::move(out.buffer());
}

FileParts readFile(const uint8_t* data, size_t size) {
    if (size == 0) throw Error(ErrorKind::Corrupt, "empty file: not a .drm file");
    if (size < sizeof kSignature || std::memcmp(data, kSignature, sizeof kSignature) != 0)
        throw Error(ErrorKind::Corrupt, "not a .drm file: the signature is missing");
    ByteReader file(data, size, "file");
    file.bytes(sizeof kSignature, "signature");
    const uint16_t version = file.u16("format version");
    if (version < kFormatVersion && version > 0)
        throw Error(ErrorKind::Unsupported, "unsupported .drm format version " + std::to_string(version) +
                    ": a pre-release format this reader does not read (it reads version " + std::to_string(kFormatVersion) +
                    "); encode the mesh again");
    if (version != kFormatVersion)
        throw Error(ErrorKind::Unsupported, "unsupported .drm format version " + std::to_string(version) +
                    ": this reader knows version " + std::to_string(kFormatVersion));

    // Each section: length, CRC-32, payload. The header comes first, and
    // says whether the optional sections (vertex order, repairs) follow.
    auto section = [&](const std::string& name, const uint8_t** payload, size_t* payloadSize) {
        *payloadSize = size_t(file.count((name + " section length").c_str(), file.remaining()));
        const uint32_t stored = file.u32((name + " section checksum").c_str());
        const size_t offset = file.offset();
        *payload = file.bytes(*payloadSize, (name + " section").c_str());
        if (sectionChecksum(*payload, *payloadSize) != stored)
            throw Error(ErrorKind::Corrupt, "corrupt file: the " + name + " section (offset " + std::to_string(offset) +
                        ") fails its checksum");
    };
    FileParts parts;
    parts.formatVersion = version;
    const uint8_t* headerPayload = nullptr;
    size_t headerSize = 0;
    section("header", &headerPayload, &headerSize);
    ByteReader header(headerPayload, headerSize, "header", size_t(headerPayload - data));
    parts.header = decodeHeader(header);
    section("connectivity", &parts.connectivity, &parts.connectivitySize);
    section("geometry", &parts.geometry, &parts.geometrySize);
    if (parts.header.keepsVertexOrder) section("vertex order", &parts.vertexOrder, &parts.vertexOrderSize);
    if (parts.header.hasRepairs) section("repairs", &parts.repairs, &parts.repairsSize);
    const size_t beforeAttributes = file.offset();
    for (uint64_t a = 0; a < parts.header.attributeSections; ++a) {
        FileParts::Payload payload{nullptr, 0};
        section("attribute " + std::to_string(a), &payload.data, &payload.size);
        parts.attributes.push_back(payload);
    }
    parts.attributeBytes = file.offset() - beforeAttributes;
    if (file.remaining() != 0)
        throw Error(ErrorKind::Corrupt, "corrupt file: " + std::to_string(file.remaining()) + " unexpected bytes after the last section");
    parts.headerBytes = size - parts.connectivitySize - parts.geometrySize - parts.vertexOrderSize - parts.repairsSize -
                        parts.attributeBytes;
    return parts;
}

}  // namespace drm
