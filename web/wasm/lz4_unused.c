/* FLANN's index classes carry file serialization code that calls lz4; the
 * codec never saves or loads an index, so in the WebAssembly build these
 * entry points exist only to satisfy the linker (the host build links the
 * system's liblz4 instead). Reaching one is a bug: it aborts. */
#include <stdlib.h>

#include <lz4.h>
#include <lz4hc.h>

int LZ4_decompress_safe(const char* src, char* dst, int compressedSize, int dstCapacity) {
    (void)src, (void)dst, (void)compressedSize, (void)dstCapacity;
    abort();
}

int LZ4_decompress_safe_continue(LZ4_streamDecode_t* stream, const char* src, char* dst, int srcSize, int dstCapacity) {
    (void)stream, (void)src, (void)dst, (void)srcSize, (void)dstCapacity;
    abort();
}

int LZ4_setStreamDecode(LZ4_streamDecode_t* stream, const char* dictionary, int dictSize) {
    (void)stream, (void)dictionary, (void)dictSize;
    abort();
}

void LZ4_resetStreamHC(LZ4_streamHC_t* stream, int compressionLevel) {
    (void)stream, (void)compressionLevel;
    abort();
}

int LZ4_compress_HC_continue(LZ4_streamHC_t* stream, const char* src, char* dst, int srcSize, int maxDstSize) {
    (void)stream, (void)src, (void)dst, (void)srcSize, (void)maxDstSize;
    abort();
}
