#include "drm_sections.h"

#include <cstring>
#include <stdexcept>

namespace drm_test {
namespace {

// LEB128 as the format writes it; unlike the codec's reader this accepts
// overlong forms, so a mutated-but-parseable length is still seen as one.
bool readVarint(const uint8_t* data, size_t size, size_t* pos, uint64_t* value) {
    *value = 0;
    for (int i = 0; i < 10; ++i) {
        if (*pos >= size) return false;
        const uint8_t byte = data[(*pos)++];
        *value |= uint64_t(byte & 0x7F) << (7 * i);
        if ((byte & 0x80) == 0) return true;
    }
    return false;
}

}  // namespace

bool parseSections(const uint8_t* data, size_t size, std::vector<SectionSpan>* sections) {
    sections->clear();
    if (size < kPreambleSize) return false;
    size_t pos = kPreambleSize;
    while (pos < size) {
        SectionSpan s;
        s.start = pos;
        uint64_t length = 0;
        if (!readVarint(data, size, &pos, &length)) return false;
        if (size - pos < 4) return false;
        s.checksumAt = pos;
        pos += 4;
        if (length > size - pos) return false;
        s.payloadAt = pos;
        s.payloadSize = size_t(length);
        pos += s.payloadSize;
        sections->push_back(s);
    }
    return !sections->empty();
}

bool parseSections(const std::vector<uint8_t>& file, std::vector<SectionSpan>* sections) {
    return parseSections(file.data(), file.size(), sections);
}

uint32_t crc32(const uint8_t* data, size_t size, uint32_t previous) {
    // Bitwise: these files are small, and a table would be one more thing
    // that could share a mistake with the codec's.
    uint32_t crc = previous ^ 0xFFFFFFFFu;
    for (size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
}

void appendVarint(std::vector<uint8_t>& out, uint64_t value) {
    for (; value >= 0x80; value >>= 7) out.push_back(uint8_t(value | 0x80));
    out.push_back(uint8_t(value));
}

uint32_t sectionChecksum(const uint8_t* preamble, const std::vector<uint8_t>& payload) {
    const unsigned version = unsigned(preamble[kSignatureSize]) | unsigned(preamble[kSignatureSize + 1]) << 8;
    const uint32_t before = version >= 2 ? crc32(preamble + kSignatureSize, 2) : 0;
    return crc32(payload.data(), payload.size(), before);
}

void appendSection(std::vector<uint8_t>& out, const std::vector<uint8_t>& payload) {
    if (out.size() < kPreambleSize) throw std::invalid_argument("appendSection: no preamble to append to");
    const uint32_t crc = sectionChecksum(out.data(), payload);
    appendVarint(out, payload.size());
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(crc >> (8 * i)));
    out.insert(out.end(), payload.begin(), payload.end());
}

std::vector<uint8_t> assemble(const uint8_t* preamble, const std::vector<std::vector<uint8_t>>& payloads) {
    std::vector<uint8_t> out(preamble, preamble + kPreambleSize);
    for (const std::vector<uint8_t>& p : payloads) appendSection(out, p);
    return out;
}

std::vector<std::vector<uint8_t>> payloadsOf(const std::vector<uint8_t>& file,
                                             const std::vector<SectionSpan>& sections) {
    std::vector<std::vector<uint8_t>> payloads;
    for (const SectionSpan& s : sections)
        payloads.emplace_back(file.begin() + std::ptrdiff_t(s.payloadAt), file.begin() + std::ptrdiff_t(s.end()));
    return payloads;
}

std::vector<uint8_t> withPayload(const std::vector<uint8_t>& file, size_t s, const std::vector<uint8_t>& payload) {
    std::vector<SectionSpan> sections;
    if (!parseSections(file, &sections) || s >= sections.size())
        throw std::invalid_argument("withPayload: not a container, or no such section");
    std::vector<std::vector<uint8_t>> payloads = payloadsOf(file, sections);
    payloads[s] = payload;
    return assemble(file.data(), payloads);
}

}  // namespace drm_test
