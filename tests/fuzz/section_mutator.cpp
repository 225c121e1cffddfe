// Mutations that get past the checksums.
//
// Each section carries a CRC-32, so nearly every byte libFuzzer changes is
// caught by readFile before any decoder sees it. This mutator instead
// mutates one section's payload with libFuzzer's own mutators and writes
// the section back with its new length and checksum; the cross-over
// combines the sections of two inputs. A few mutations in each batch still
// work on the raw bytes, so the container checks (signature, version,
// lengths, checksums, trailing bytes) stay fuzzed too.
#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "drm_sections.h"

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t maxSize);

namespace {

// One mutation in this many ignores the layout.
constexpr unsigned kRawMutationOdds = 8;

size_t store(const std::vector<uint8_t>& file, uint8_t* out, size_t maxSize) {
    if (file.size() > maxSize) return 0;
    std::memcpy(out, file.data(), file.size());
    return file.size();
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t maxSize, unsigned int seed) {
    std::minstd_rand rng(seed);
    std::vector<drm_test::SectionSpan> sections;
    if (rng() % kRawMutationOdds == 0 || !drm_test::parseSections(data, size, &sections))
        return LLVMFuzzerMutate(data, size, maxSize);

    const std::vector<uint8_t> file(data, data + size);
    std::vector<std::vector<uint8_t>> payloads = drm_test::payloadsOf(file, sections);
    const size_t s = rng() % payloads.size();
    std::vector<uint8_t>& payload = payloads[s];
    // Room for the payload to grow: whatever maxSize leaves after the rest
    // of the file, less the bytes a longer length varint may take.
    const size_t rest = size - payload.size();
    if (rest + 4 >= maxSize) return LLVMFuzzerMutate(data, size, maxSize);
    const size_t room = maxSize - rest - 4;
    const size_t oldSize = payload.size();
    payload.resize(std::max(room, oldSize));
    payload.resize(LLVMFuzzerMutate(payload.data(), oldSize, room));

    const size_t written = store(drm_test::assemble(file.data(), payloads), data, maxSize);
    return written > 0 ? written : LLVMFuzzerMutate(data, size, maxSize);
}

extern "C" size_t LLVMFuzzerCustomCrossOver(const uint8_t* data1, size_t size1, const uint8_t* data2, size_t size2,
                                            uint8_t* out, size_t maxOutSize, unsigned int seed) {
    std::minstd_rand rng(seed);
    std::vector<drm_test::SectionSpan> first, second;
    if (!drm_test::parseSections(data1, size1, &first) || !drm_test::parseSections(data2, size2, &second))
        return 0;
    const std::vector<uint8_t> a(data1, data1 + size1), b(data2, data2 + size2);
    std::vector<std::vector<uint8_t>> payloads = drm_test::payloadsOf(a, first);
    const std::vector<std::vector<uint8_t>> others = drm_test::payloadsOf(b, second);
    // Each section from either parent (a header of one mesh over the ranks
    // of another, say), keeping the first parent's section count.
    for (size_t s = 0; s < payloads.size() && s < others.size(); ++s)
        if (rng() % 2) payloads[s] = others[s];
    return store(drm_test::assemble(a.data(), payloads), out, maxOutSize);
}
