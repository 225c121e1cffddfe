// drm-peer-bench: one small interface every compared codec is put behind, so
// the runner times, checks and reports them all the same way.
#ifndef DRM_TOOLS_BENCH_PEER_H
#define DRM_TOOLS_BENCH_PEER_H

#include <drmcodec/drmcodec.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace drm {
namespace peers {

// What a codec made of one mesh.
struct Compressed {
    std::vector<uint8_t> bytes;      // everything the decoder needs: the "file"
    uint64_t connectivityBytes = 0;  // the part of `bytes` that codes the triangles
};

// What decoding gave back, to check that no triangle was lost or added.
struct DecodedCounts {
    uint64_t vertices = 0;
    uint64_t triangles = 0;
};

// A codec under test. Calls come in this order for each mesh: load (not
// timed), then encode and decode, each several times (timed). Every method
// throws std::exception with a sentence for the table when the codec refuses
// the mesh or fails.
class Peer {
public:
    virtual ~Peer() = default;

    // Short column title, e.g. "draco cl10".
    virtual std::string name() const = 0;
    // One line for the report: version, settings, what connectivity means here.
    virtual std::string description() const = 0;

    // Converts the mesh to the codec's own input form. Not timed: that is the
    // application's format conversion, not the codec's work.
    virtual void load(const drm::Mesh& mesh) = 0;
    // Compresses the loaded mesh, including any reordering the codec relies on.
    virtual Compressed encode() = 0;
    // Decompresses into the codec's own output form.
    virtual DecodedCounts decode(const std::vector<uint8_t>& bytes) = 0;
};

// drm::encode with default options, or with Levers::none() (the paper's method).
std::unique_ptr<Peer> makeDrmPeer(bool paperMethod, int bits);
// Draco Edgebreaker at a compression level 0..10 (speed = 10 - level, as the
// draco_encoder tool maps -cl), positions quantized to `bits`.
std::unique_ptr<Peer> makeDracoPeer(int compressionLevel, int bits);
// meshoptimizer's vertex-cache and vertex-fetch optimizations, index and
// vertex codecs, then zstd at `zstdLevel` on each stream.
std::unique_ptr<Peer> makeMeshoptPeer(int bits, int zstdLevel);
// OpenCTM MG2 at LZMA level 1 (its default), vertex precision = one step of the `bits` grid.
std::unique_ptr<Peer> makeOpenctmPeer(int bits);

}  // namespace peers
}  // namespace drm

#endif  // DRM_TOOLS_BENCH_PEER_H
