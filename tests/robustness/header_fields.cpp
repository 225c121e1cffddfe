#include "header_fields.h"

#include <cstring>

#include "drm_sections.h"

namespace drm_test {
namespace {

class Reader {
public:
    explicit Reader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
    bool fixed(int count, uint64_t* value) {
        if (bytes_.size() - pos_ < size_t(count)) return false;
        *value = 0;
        for (int i = 0; i < count; ++i) *value |= uint64_t(bytes_[pos_++]) << (8 * i);
        return true;
    }
    bool varint(uint64_t* value) {
        *value = 0;
        for (int i = 0; i < 10 && pos_ < bytes_.size(); ++i) {
            const uint8_t byte = bytes_[pos_++];
            *value |= uint64_t(byte & 0x7F) << (7 * i);
            if ((byte & 0x80) == 0) return true;
        }
        return false;
    }
    bool atEnd() const { return pos_ == bytes_.size(); }

private:
    const std::vector<uint8_t>& bytes_;
    size_t pos_ = 0;
};

double doubleOf(uint64_t bits) {
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return d;
}

void appendFixed(std::vector<uint8_t>& out, uint64_t value, int count) {
    for (int i = 0; i < count; ++i) out.push_back(uint8_t(value >> (8 * i)));
}

void appendDouble(std::vector<uint8_t>& out, double d) {
    uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    appendFixed(out, bits, 8);
}

}  // namespace

bool readHeader(const std::vector<uint8_t>& payload, HeaderFields* h) {
    Reader in(payload);
    uint64_t v = 0;
    if (!in.fixed(2, &v)) return false;
    h->flags = uint16_t(v);
    uint8_t* bytes[4] = {&h->bits, &h->predictor, &h->connectivityCoder, &h->geometryCoder};
    for (uint8_t* b : bytes) {
        if (!in.fixed(1, &v)) return false;
        *b = uint8_t(v);
    }
    for (double& o : h->origin) {
        if (!in.fixed(8, &v)) return false;
        o = doubleOf(v);
    }
    if (!in.fixed(8, &v)) return false;
    h->step = doubleOf(v);
    if (!in.varint(&h->vertexCount) || !in.varint(&h->faceCount)) return false;
    if ((h->flags & kRepairsFlag) && !in.varint(&h->copyCount)) return false;
    if (!in.varint(&h->componentCount)) return false;
    return in.atEnd();
}

std::vector<uint8_t> writeHeader(const HeaderFields& h) {
    std::vector<uint8_t> out;
    appendFixed(out, h.flags, 2);
    for (uint8_t b : {h.bits, h.predictor, h.connectivityCoder, h.geometryCoder}) out.push_back(b);
    for (double o : h.origin) appendDouble(out, o);
    appendDouble(out, h.step);
    appendVarint(out, h.vertexCount);
    appendVarint(out, h.faceCount);
    if (h.flags & kRepairsFlag) appendVarint(out, h.copyCount);
    appendVarint(out, h.componentCount);
    return out;
}

}  // namespace drm_test
