// The `drm` command's global operator new: asks the kernel for transparent
// huge pages under the heap's large blocks.
//
// Encoding or decoding a large mesh fills tables of several megabytes
// (neighbour lists, half-edge tables, the grid), most of them touched once
// and then read at random: with 4 KiB pages the kernel takes a fault and
// zeroes a page every 4 KiB, and the random reads miss the TLB. Where the
// kernel gives huge pages only on request (`madvise` in
// /sys/kernel/mm/transparent_hugepage/enabled, Debian's default), nothing
// asked for them. glibc can (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), but
// only from the environment at start-up; so the tool asks itself. Where
// huge pages are always or never given, the advice changes nothing.
// What it buys: docs/tuning.md ("The drm tool").
//
// When a block of kAdviseFrom bytes or more is allocated, the advice covers
// the 2 MiB pages it lies in and, when it lies in the main heap, every page
// from it up to the heap's end: the heap grows by main.cpp's M_TOP_PAD at a time, and
// the smaller blocks carved from that pad later (vectors of vectors, the
// coders' tables) are advised too. Advice is a hint on the address range:
// it changes no data, so the other allocations sharing those pages are
// unaffected but for the page size. Blocks come from malloc, so the default
// operator delete (free) releases them.
//
// Process-wide, so the tool's choice, not the library's (like main.cpp's
// mallopt).
#include <cstdint>
#include <cstdlib>
#include <new>

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;  // x86-64, and arm64 with 4 KiB base pages
constexpr std::size_t kAdviseFrom = std::size_t(256) << 10;

#if defined(__linux__) && defined(MADV_HUGEPAGE)
std::uintptr_t roundDown(std::uintptr_t a) { return a & ~(kHugePage - 1); }
std::uintptr_t roundUp(std::uintptr_t a) { return (a + kHugePage - 1) & ~(kHugePage - 1); }

// The heap's start as the program started (static initialisation, before
// any large block): blocks at or above it and below the break are the main
// heap's; others (mapped blocks, other threads' arenas) are advised alone.
const std::uintptr_t kHeapStart = reinterpret_cast<std::uintptr_t>(sbrk(0));

void adviseHugePages(void* block, std::size_t size) {
    const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(block), last = first + size;
    const std::uintptr_t heapEnd = reinterpret_cast<std::uintptr_t>(sbrk(0));
    const bool inHeap = first >= kHeapStart && last <= heapEnd;
    const std::uintptr_t begin = roundDown(first), end = roundUp(inHeap ? heapEnd : last);
    // A hint: where the kernel refuses it, the pages stay small.
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}
#else
void adviseHugePages(void*, std::size_t) {}
#endif

}  // namespace

// The other forms but the aligned ones (arrays, nothrow) call this one in
// libstdc++.
void* operator new(std::size_t size) {
    if (size == 0) size = 1;
    void* block;
    while ((block = std::malloc(size)) == nullptr) {
        const std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
    if (size >= kAdviseFrom) adviseHugePages(block, size);
    return block;
}
