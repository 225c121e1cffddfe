// meshoptimizer's codecs as its documentation recommends using them: reorder
// for the vertex cache, then for vertex fetch, encode the index and vertex
// buffers, and put a general-purpose compressor (here zstd) on top.
//
// Positions are drm's grid coordinates (drm::makeGrid / drm::quantize), so
// the quantization is exactly the other codecs'. They are stored as four
// uint16 per vertex: the vertex codec needs a stride that is a multiple of
// four, and the always-zero fourth channel costs almost nothing.
//
// Stream: vertex count, index count, compressed index size (uint32 LE each),
// then zstd(index codec), then zstd(vertex codec). Connectivity is the
// zstd(index codec) part.
#include "peer.h"

#include <meshoptimizer.h>
#include <zstd.h>

#include <stdexcept>

namespace drm {
namespace peers {
namespace {

constexpr size_t kVertexSize = 4 * sizeof(uint16_t);
constexpr size_t kHeaderSize = 3 * sizeof(uint32_t);

void putU32(std::vector<uint8_t>& out, uint64_t value) {
    if (value > UINT32_MAX) throw std::runtime_error("meshopt stream: count over 2^32");
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(value >> (8 * i)));
}

uint32_t getU32(const std::vector<uint8_t>& in, size_t offset) {
    uint32_t value = 0;
    for (int i = 0; i < 4; ++i) value |= uint32_t(in[offset + i]) << (8 * i);
    return value;
}

std::vector<uint8_t> zstdCompress(const std::vector<uint8_t>& data, int level) {
    std::vector<uint8_t> out(ZSTD_compressBound(data.size()));
    const size_t size = ZSTD_compress(out.data(), out.size(), data.data(), data.size(), level);
    if (ZSTD_isError(size)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(size));
    out.resize(size);
    return out;
}

// Decompresses exactly `expected` bytes from in[begin, end).
std::vector<uint8_t> zstdDecompress(const uint8_t* begin, const uint8_t* end, size_t expected) {
    std::vector<uint8_t> out(expected);
    const size_t size = ZSTD_decompress(out.data(), out.size(), begin, size_t(end - begin));
    if (ZSTD_isError(size)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(size));
    if (size != expected) throw std::runtime_error("zstd: unexpected decompressed size");
    return out;
}

class MeshoptPeer : public Peer {
public:
    MeshoptPeer(int bits, int zstdLevel) : bits_(bits), zstdLevel_(zstdLevel) {
        // Version 1 of the index codec codes triangles better than 0 and is
        // what current meshoptimizer (and glTF's EXT_meshopt_compression) uses.
        meshopt_encodeIndexVersion(1);
    }

    std::string name() const override { return "meshopt+zstd"; }

    std::string description() const override {
        // MESHOPTIMIZER_VERSION is major * 1000 + minor * 10: 180 is 0.18.
        return "meshoptimizer " + std::to_string(MESHOPTIMIZER_VERSION / 1000) + "." +
               std::to_string(MESHOPTIMIZER_VERSION % 1000 / 10) + " (optimizeVertexCache, optimizeVertexFetch, index codec v1, " +
               "vertex codec on " + std::to_string(bits_) + "-bit grid coordinates as 4 x uint16) + zstd " +
               ZSTD_versionString() + " level " + std::to_string(zstdLevel_) +
               " on each stream; decoding stops at the grid coordinates; connectivity = zstd(index codec output)";
    }

    void load(const drm::Mesh& mesh) override {
        if (bits_ > 16) throw std::runtime_error("meshopt peer: grid coordinates over 16 bits do not fit its uint16 vertices");
        const drm::Grid grid = drm::makeGrid(mesh.positions, bits_);
        const std::vector<int32_t> quantized = drm::quantize(mesh.positions, grid);
        vertexCount_ = mesh.vertexCount();
        vertices_.assign(vertexCount_ * 4, 0);
        for (size_t v = 0; v < vertexCount_; ++v)
            for (int k = 0; k < 3; ++k) vertices_[4 * v + k] = uint16_t(quantized[3 * v + k]);
        indices_.assign(mesh.triangles.begin(), mesh.triangles.end());
    }

    Compressed encode() override {
        const size_t indexCount = indices_.size();
        std::vector<unsigned int> indices(indexCount);
        meshopt_optimizeVertexCache(indices.data(), indices_.data(), indexCount, vertexCount_);
        std::vector<uint16_t> vertices(vertices_.size());
        // Also renumbers `indices`; drops vertices no triangle uses.
        const size_t usedVertices =
            meshopt_optimizeVertexFetch(vertices.data(), indices.data(), indexCount, vertices_.data(), vertexCount_, kVertexSize);

        std::vector<uint8_t> indexCode(meshopt_encodeIndexBufferBound(indexCount, usedVertices));
        indexCode.resize(meshopt_encodeIndexBuffer(indexCode.data(), indexCode.size(), indices.data(), indexCount));
        std::vector<uint8_t> vertexCode(meshopt_encodeVertexBufferBound(usedVertices, kVertexSize));
        vertexCode.resize(
            meshopt_encodeVertexBuffer(vertexCode.data(), vertexCode.size(), vertices.data(), usedVertices, kVertexSize));
        if (indexCode.empty() || vertexCode.empty()) throw std::runtime_error("meshopt encoding failed");

        const std::vector<uint8_t> indexPacked = zstdCompress(indexCode, zstdLevel_);
        const std::vector<uint8_t> vertexPacked = zstdCompress(vertexCode, zstdLevel_);
        Compressed out;
        putU32(out.bytes, usedVertices);
        putU32(out.bytes, indexCount);
        putU32(out.bytes, indexPacked.size());
        out.bytes.insert(out.bytes.end(), indexPacked.begin(), indexPacked.end());
        out.bytes.insert(out.bytes.end(), vertexPacked.begin(), vertexPacked.end());
        out.connectivityBytes = indexPacked.size();
        return out;
    }

    DecodedCounts decode(const std::vector<uint8_t>& bytes) override {
        if (bytes.size() < kHeaderSize) throw std::runtime_error("meshopt stream: truncated header");
        const size_t vertexCount = getU32(bytes, 0);
        const size_t indexCount = getU32(bytes, 4);
        const size_t indexPackedSize = getU32(bytes, 8);
        if (indexPackedSize > bytes.size() - kHeaderSize) throw std::runtime_error("meshopt stream: truncated indices");
        const uint8_t* indexBegin = bytes.data() + kHeaderSize;
        const uint8_t* vertexBegin = indexBegin + indexPackedSize;

        // The index and vertex codecs do not record their output size; zstd
        // frames do (ZSTD_compress writes the content size).
        const unsigned long long indexCodeSize = ZSTD_getFrameContentSize(indexBegin, indexPackedSize);
        const unsigned long long vertexCodeSize = ZSTD_getFrameContentSize(vertexBegin, size_t(bytes.data() + bytes.size() - vertexBegin));
        if (indexCodeSize >= ZSTD_CONTENTSIZE_ERROR || vertexCodeSize >= ZSTD_CONTENTSIZE_ERROR)
            throw std::runtime_error("meshopt stream: zstd frame without content size");
        const std::vector<uint8_t> indexCode = zstdDecompress(indexBegin, vertexBegin, size_t(indexCodeSize));
        const std::vector<uint8_t> vertexCode = zstdDecompress(vertexBegin, bytes.data() + bytes.size(), size_t(vertexCodeSize));

        std::vector<unsigned int> indices(indexCount);
        std::vector<uint16_t> vertices(vertexCount * 4);
        if (meshopt_decodeIndexBuffer(indices.data(), indexCount, sizeof(unsigned int), indexCode.data(), indexCode.size()) != 0 ||
            meshopt_decodeVertexBuffer(vertices.data(), vertexCount, kVertexSize, vertexCode.data(), vertexCode.size()) != 0)
            throw std::runtime_error("meshopt decoding failed");
        return {vertexCount, indexCount / 3};
    }

private:
    int bits_;
    int zstdLevel_;
    size_t vertexCount_ = 0;
    std::vector<uint16_t> vertices_;
    std::vector<unsigned int> indices_;
};

}  // namespace

std::unique_ptr<Peer> makeMeshoptPeer(int bits, int zstdLevel) {
    return std::unique_ptr<Peer>(new MeshoptPeer(bits, zstdLevel));
}

}  // namespace peers
}  // namespace drm
