// The .drm container as docs/format.md lays it out (signature, u16 version,
// then sections of [varint length, u32 CRC-32, payload]), read and rewritten
// independently of the codec's own reader.
//
// Robustness tests and the fuzzer use it to corrupt a payload and then give
// it a fresh length and checksum, so that the corruption gets past the CRCs
// and reaches the decoder's semantic checks. It knows nothing of what the
// sections mean, so it keeps working when a section is added (the header's
// flags decide whether a vertex-order section follows the geometry).
#ifndef DRM_TEST_DRM_SECTIONS_H
#define DRM_TEST_DRM_SECTIONS_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm_test {

constexpr size_t kSignatureSize = 8;
constexpr size_t kPreambleSize = 10;  // signature + u16 version

struct SectionSpan {
    size_t start = 0;          // file offset of the length varint
    size_t checksumAt = 0;     // file offset of the CRC-32
    size_t payloadAt = 0;      // file offset of the payload
    size_t payloadSize = 0;
    size_t end() const { return payloadAt + payloadSize; }
};

// The sections of a file that is laid out as a container: a preamble, then
// whole sections up to the last byte (checksums are not checked). Returns
// false, leaving *sections unspecified, for anything else.
bool parseSections(const uint8_t* data, size_t size, std::vector<SectionSpan>* sections);
bool parseSections(const std::vector<uint8_t>& file, std::vector<SectionSpan>* sections);

// The CRC-32 of docs/format.md (reflected, polynomial 0xEDB88320, initial
// value and final xor 0xFFFFFFFF), continuing from that of what came before.
uint32_t crc32(const uint8_t* data, size_t size, uint32_t previous = 0);
// A section's checksum in a file with this preamble: it covers the two
// version bytes before the payload, or the payload alone when the preamble
// says version 1, as that pre-release version's files have it
// (docs/format.md, "Earlier versions").
uint32_t sectionChecksum(const uint8_t* preamble, const std::vector<uint8_t>& payload);

void appendVarint(std::vector<uint8_t>& out, uint64_t value);
// Appends a section to out, which starts with the file's preamble.
void appendSection(std::vector<uint8_t>& out, const std::vector<uint8_t>& payload);

// A container from a 10-byte preamble and payloads, with correct lengths
// and checksums.
std::vector<uint8_t> assemble(const uint8_t* preamble, const std::vector<std::vector<uint8_t>>& payloads);

// The payloads of a parsed file, in order.
std::vector<std::vector<uint8_t>> payloadsOf(const std::vector<uint8_t>& file,
                                             const std::vector<SectionSpan>& sections);

// file with section s's payload replaced (lengths and checksums rewritten).
// file must parse; s must be one of its sections.
std::vector<uint8_t> withPayload(const std::vector<uint8_t>& file, size_t s, const std::vector<uint8_t>& payload);

}  // namespace drm_test

#endif  // DRM_TEST_DRM_SECTIONS_H
