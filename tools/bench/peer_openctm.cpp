// OpenCTM's MG2 method (fixed-point positions, LZMA-packed streams), at the
// library's default LZMA level.
//
// MG2 takes an absolute vertex precision rather than a bit count; one step of
// drm's grid (drm::makeGrid) gives the same worst-case error as the others.
//
// Connectivity is read from the file's own layout (OpenCTM format spec,
// MG2 section): after the file header and the "MG2H" header come packed
// chunks -- a four-letter tag, a uint32 packed size, 5 bytes of LZMA
// properties, the packed data -- and the triangles are the "INDX" chunk.
#include "peer.h"

#include <openctm.h>

#include <cstring>
#include <stdexcept>

namespace drm {
namespace peers {
namespace {

// The library's default. Level 9 saves under 0.7% on bunny, fandisk and igea
// but spends about half a second per file setting up its 64 MB dictionary,
// which would swamp every time in the tables.
constexpr int kLzmaLevel = 1;

// Owns a CTMcontext for one call.
class Context {
public:
    explicit Context(CTMenum mode) : context_(ctmNewContext(mode)) {
        if (!context_) throw std::runtime_error("OpenCTM: cannot create a context");
    }
    ~Context() { ctmFreeContext(context_); }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    CTMcontext get() const { return context_; }
    void check(const char* stage) const {
        const CTMenum error = ctmGetError(context_);
        if (error != CTM_NONE) throw std::runtime_error(std::string("OpenCTM ") + stage + " failed: " + ctmErrorString(error));
    }

private:
    CTMcontext context_;
};

CTMuint CTMCALL appendBytes(const void* data, CTMuint count, void* userData) {
    auto* out = static_cast<std::vector<uint8_t>*>(userData);
    const auto* bytes = static_cast<const uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + count);
    return count;
}

struct Reader {
    const std::vector<uint8_t>* bytes;
    size_t offset;
};

CTMuint CTMCALL readBytes(void* data, CTMuint count, void* userData) {
    auto* reader = static_cast<Reader*>(userData);
    const size_t available = reader->bytes->size() - reader->offset;
    const size_t n = count < available ? count : available;
    std::memcpy(data, reader->bytes->data() + reader->offset, n);
    reader->offset += n;
    return CTMuint(n);
}

uint32_t readU32(const std::vector<uint8_t>& bytes, size_t offset) {
    if (offset + 4 > bytes.size()) throw std::runtime_error("OpenCTM file: truncated");
    uint32_t value = 0;
    for (int i = 0; i < 4; ++i) value |= uint32_t(bytes[offset + i]) << (8 * i);
    return value;
}

bool hasTag(const std::vector<uint8_t>& bytes, size_t offset, const char* tag) {
    return offset + 4 <= bytes.size() && std::memcmp(bytes.data() + offset, tag, 4) == 0;
}

// Size of the "INDX" chunk (tag, size, LZMA properties, data) of an MG2 file.
uint64_t indexChunkBytes(const std::vector<uint8_t>& file) {
    // File header: "OCTM", version, method, vertex count, triangle count,
    // UV map count, attribute map count, flags, then the comment string.
    if (!hasTag(file, 0, "OCTM") || !hasTag(file, 8, "MG2\0")) throw std::runtime_error("OpenCTM file: not MG2");
    size_t offset = 32;
    offset += 4 + size_t(readU32(file, offset));  // comment: length, then text
    // "MG2H": vertex and normal precision, grid min[3], max[3], division[3].
    if (!hasTag(file, offset, "MG2H")) throw std::runtime_error("OpenCTM file: no MG2H header");
    offset += 4 + 8 * 4 + 3 * 4;
    while (offset < file.size()) {
        const size_t chunk = 4 + 4 + 5 + size_t(readU32(file, offset + 4));
        if (hasTag(file, offset, "INDX")) return chunk;
        offset += chunk;
    }
    throw std::runtime_error("OpenCTM file: no INDX chunk");
}

class OpenctmPeer : public Peer {
public:
    explicit OpenctmPeer(int bits) : bits_(bits) {}

    std::string name() const override { return "openctm mg2"; }

    std::string description() const override {
        return "OpenCTM 1.0.3 (Debian libopenctm), MG2, LZMA level " + std::to_string(kLzmaLevel) +
               " (the library's default), vertex precision = one step of the " + std::to_string(bits_) +
               "-bit grid; connectivity = the INDX chunk";
    }

    void load(const drm::Mesh& mesh) override {
        positions_ = mesh.positions;
        indices_.assign(mesh.triangles.begin(), mesh.triangles.end());
        step_ = float(drm::makeGrid(mesh.positions, bits_).step);
    }

    Compressed encode() override {
        Context context(CTM_EXPORT);
        ctmCompressionMethod(context.get(), CTM_METHOD_MG2);
        ctmCompressionLevel(context.get(), kLzmaLevel);
        ctmVertexPrecision(context.get(), step_);
        ctmDefineMesh(context.get(), positions_.data(), CTMuint(positions_.size() / 3), indices_.data(),
                      CTMuint(indices_.size() / 3), nullptr);
        context.check("mesh definition");
        Compressed out;
        ctmSaveCustom(context.get(), appendBytes, &out.bytes);
        context.check("encoding");
        out.connectivityBytes = indexChunkBytes(out.bytes);
        return out;
    }

    DecodedCounts decode(const std::vector<uint8_t>& bytes) override {
        Context context(CTM_IMPORT);
        Reader reader{&bytes, 0};
        ctmLoadCustom(context.get(), readBytes, &reader);
        context.check("decoding");
        return {ctmGetInteger(context.get(), CTM_VERTEX_COUNT), ctmGetInteger(context.get(), CTM_TRIANGLE_COUNT)};
    }

private:
    int bits_;
    std::vector<float> positions_;
    std::vector<CTMuint> indices_;
    float step_ = 1;
};

}  // namespace

std::unique_ptr<Peer> makeOpenctmPeer(int bits) {
    return std::unique_ptr<Peer>(new OpenctmPeer(bits));
}

}  // namespace peers
}  // namespace drm
