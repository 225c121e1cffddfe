// The `drm` tool's operator new (tools/huge_pages.cpp), linked into this
// test as into the tool: a large block, once touched, lies in transparent
// huge pages where the kernel gives them on request, and still holds what
// was written to it.
#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

namespace {

std::string thpMode() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    std::getline(in, line);
    return line;  // e.g. "always [madvise] never"
}

// AnonHugePages of the mapping holding `address`, in KiB (-1 if not found).
long hugePagesKiBAt(const void* address) {
    const uintptr_t a = reinterpret_cast<uintptr_t>(address);
    std::ifstream in("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> begin >> dash >> end && dash == '-') {
            inside = begin <= a && a < end;
            continue;
        }
        if (inside && line.rfind("AnonHugePages:", 0) == 0) return std::stol(line.substr(14));
    }
    return -1;
}

bool hugePagesOnRequest() {
    const std::string mode = thpMode();
    return mode.find("[madvise]") != std::string::npos || mode.find("[always]") != std::string::npos;
}

// Fills a block, checks it reads back, and returns its huge pages.
long touchedHugePagesKiB(size_t size) {
    std::unique_ptr<uint8_t[]> block(new uint8_t[size]);
    for (size_t i = 0; i < size; ++i) block[i] = uint8_t(i * 7 + 3);
    for (size_t i = 0; i < size; i += 4093)
        if (block[i] != uint8_t(i * 7 + 3)) return -2;
    return hugePagesKiBAt(block.get() + size / 2);
}

// A block over glibc's mmap threshold is mapped on its own. 64 MiB hold 31
// whole 2 MiB pages wherever the block starts; a kernel short of free huge
// pages may give fewer, but not none.
TEST(HugePages, MappedBlock) {
    if (!hugePagesOnRequest()) GTEST_SKIP() << "transparent huge pages are not given on request here: " << thpMode();
    EXPECT_GE(touchedHugePagesKiB(size_t(64) << 20), 2048);
}

// Under the tool's mallopt settings (main.cpp), a block below 32 MiB comes
// from the heap: the advice then covers it and the heap above it.
TEST(HugePages, HeapBlock) {
    if (!hugePagesOnRequest()) GTEST_SKIP() << "transparent huge pages are not given on request here: " << thpMode();
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TOP_PAD, 16 << 20);
    EXPECT_GE(touchedHugePagesKiB(size_t(12) << 20), 2048);
}

}  // namespace
