// Draco's Edgebreaker mesh coder, with positions quantized as drm quantizes
// them (one cubic step over the bounding box).
//
// Connectivity is measured inside the real buffer rather than estimated:
// Draco writes its stream in fixed stages (header, encoder data, the mesh's
// connectivity, then the attributes), and the connectivity stage is one
// protected virtual method of MeshEdgebreakerEncoder. A subclass records the
// buffer size before and after that stage; the file itself is unchanged, and
// load() checks it is byte-identical to what draco::Encoder writes for the
// same options, so the measured bytes are those of the public API's output.
#include "peer.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/compression/mesh/mesh_edgebreaker_encoder.h>
#include <draco/core/draco_version.h>
#include <draco/mesh/mesh.h>

#include <cstring>
#include <stdexcept>

namespace drm {
namespace peers {
namespace {

// MeshEdgebreakerEncoder that remembers how many bytes its connectivity
// stage wrote: the Edgebreaker symbols, split and hole data, and the vertex
// and face counts that open that stage.
class ConnectivityMeasuringEncoder : public draco::MeshEdgebreakerEncoder {
public:
    size_t connectivityBytes() const { return connectivityBytes_; }

protected:
    draco::Status EncodeConnectivity() override {
        const size_t before = buffer()->size();
        draco::Status status = draco::MeshEdgebreakerEncoder::EncodeConnectivity();
        connectivityBytes_ = buffer()->size() - before;
        return status;
    }

private:
    size_t connectivityBytes_ = 0;
};

class DracoPeer : public Peer {
public:
    DracoPeer(int compressionLevel, int bits) : level_(compressionLevel), bits_(bits) {
        // draco_encoder maps "-cl N" to speed 10 - N for encoding and decoding.
        const int speed = 10 - compressionLevel;
        encoder_.SetSpeedOptions(speed, speed);
        encoder_.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
        encoder_.SetEncodingMethod(draco::MESH_EDGEBREAKER_ENCODING);
    }

    std::string name() const override { return "draco cl" + std::to_string(level_); }

    std::string description() const override {
        return std::string("Draco ") + draco::kDracoVersion + ", Edgebreaker, compression level " + std::to_string(level_) +
               " (speed " + std::to_string(10 - level_) + "), positions only, " + std::to_string(bits_) +
               "-bit quantization; connectivity = the bytes written by the Edgebreaker connectivity stage";
    }

    void load(const drm::Mesh& input) override {
        mesh_.reset(new draco::Mesh());
        const size_t vertexCount = input.vertexCount();
        mesh_->set_num_points(static_cast<uint32_t>(vertexCount));
        draco::GeometryAttribute position;
        position.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false, sizeof(float) * 3, 0);
        // Identity mapping: one position value per point, nothing merged, so
        // Draco sees the same vertices and faces as the other codecs.
        const int attribute = mesh_->AddAttribute(position, true, static_cast<uint32_t>(vertexCount));
        for (size_t v = 0; v < vertexCount; ++v)
            mesh_->attribute(attribute)->SetAttributeValue(draco::AttributeValueIndex(static_cast<uint32_t>(v)),
                                                           &input.positions[3 * v]);
        mesh_->SetNumFaces(input.faceCount());
        for (size_t f = 0; f < input.faceCount(); ++f) {
            draco::Mesh::Face face;
            for (int k = 0; k < 3; ++k) face[k] = draco::PointIndex(input.triangles[3 * f + k]);
            mesh_->SetFace(draco::FaceIndex(static_cast<uint32_t>(f)), face);
        }

        draco::EncoderBuffer reference;
        check(encoder_.EncodeMeshToBuffer(*mesh_, &reference), "encoding");
        reference_.assign(reference.data(), reference.data() + reference.size());
    }

    Compressed encode() override {
        // What draco::Encoder::EncodeMeshToBuffer does, with our encoder class.
        const draco::EncoderOptions options = encoder_.CreateExpertEncoderOptions(*mesh_);
        ConnectivityMeasuringEncoder encoder;
        encoder.SetMesh(*mesh_);
        draco::EncoderBuffer buffer;
        check(encoder.Encode(options, &buffer), "encoding");
        Compressed out;
        out.bytes.assign(buffer.data(), buffer.data() + buffer.size());
        out.connectivityBytes = encoder.connectivityBytes();
        if (out.bytes.size() != reference_.size() || std::memcmp(out.bytes.data(), reference_.data(), reference_.size()) != 0)
            throw std::runtime_error("measured Draco buffer differs from draco::Encoder's output");
        return out;
    }

    DecodedCounts decode(const std::vector<uint8_t>& bytes) override {
        draco::DecoderBuffer buffer;
        buffer.Init(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        draco::Decoder decoder;
        auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
        check(decoded.status(), "decoding");
        const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
        return {mesh->num_points(), mesh->num_faces()};
    }

private:
    static void check(const draco::Status& status, const char* stage) {
        if (!status.ok()) throw std::runtime_error(std::string("Draco ") + stage + " failed: " + status.error_msg_string());
    }

    int level_;
    int bits_;
    draco::Encoder encoder_;
    std::unique_ptr<draco::Mesh> mesh_;
    std::vector<char> reference_;
};

}  // namespace

std::unique_ptr<Peer> makeDracoPeer(int compressionLevel, int bits) {
    return std::unique_ptr<Peer>(new DracoPeer(compressionLevel, bits));
}

}  // namespace peers
}  // namespace drm
