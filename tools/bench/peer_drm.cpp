// drm itself, through its public API exactly as an application calls it.
#include "peer.h"

namespace drm {
namespace peers {
namespace {

class DrmPeer : public Peer {
public:
    DrmPeer(bool paperMethod, int bits) : paperMethod_(paperMethod) {
        options_.bits = bits;
        // Everything else stays at the library's defaults: these are the
        // numbers a user of `drm encode` gets.
        if (paperMethod_) {
            options_.levers = drm::Levers::none();
            options_.connectivity = drm::ConnectivityCoder::Ranks;
        }
    }

    std::string name() const override { return paperMethod_ ? "drm paper" : "drm"; }

    std::string description() const override {
        return std::string("drm ") + drm::version() +
               (paperMethod_ ? ", default options but --levers none --connectivity ranks (the paper's method as published)"
                             : ", default options (all levers, spanning-tree geometry; the distance ranks or, where the file is "
                               "smaller, the topological coder)") +
               "; connectivity = the connectivity section (Stats::connectivityBytes)";
    }

    void load(const drm::Mesh& mesh) override { mesh_ = mesh; }

    Compressed encode() override {
        drm::Encoded encoded = drm::encode(mesh_, options_);
        Compressed out;
        out.connectivityBytes = encoded.stats.connectivityBytes;
        out.bytes = std::move(encoded.bytes);
        return out;
    }

    DecodedCounts decode(const std::vector<uint8_t>& bytes) override {
        const drm::Decoded decoded = drm::decode(bytes);
        return {decoded.mesh.vertexCount(), decoded.mesh.faceCount()};
    }

private:
    bool paperMethod_;
    drm::EncodeOptions options_;
    drm::Mesh mesh_;
};

}  // namespace

std::unique_ptr<Peer> makeDrmPeer(bool paperMethod, int bits) {
    return std::unique_ptr<Peer>(new DrmPeer(paperMethod, bits));
}

}  // namespace peers
}  // namespace drm
