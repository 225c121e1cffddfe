// The header payload of docs/format.md as named fields, read and written by
// the tests (not by the codec), so a test can change one field and rewrite
// the section with a valid checksum.
#ifndef DRM_TEST_HEADER_FIELDS_H
#define DRM_TEST_HEADER_FIELDS_H

#include <cstdint>
#include <vector>

namespace drm_test {

constexpr uint16_t kRepairsFlag = 64;  // flag bit 6: a vertex copy count follows the face count

struct HeaderFields {
    uint16_t flags = 0;
    uint8_t bits = 0;
    uint8_t predictor = 0;
    uint8_t connectivityCoder = 0;
    uint8_t geometryCoder = 0;
    double origin[3] = {0, 0, 0};
    double step = 0;
    uint64_t vertexCount = 0;
    uint64_t faceCount = 0;
    uint64_t copyCount = 0;               // present only with kRepairsFlag
    uint64_t componentCount = 0;          // written as is
};

// False if payload is not exactly a header as the format describes it.
bool readHeader(const std::vector<uint8_t>& payload, HeaderFields* h);
std::vector<uint8_t> writeHeader(const HeaderFields& h);

}  // namespace drm_test

#endif  // DRM_TEST_HEADER_FIELDS_H
