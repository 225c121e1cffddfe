// The native decoder's time on .drm files, the reference for the
// WebAssembly build's: the codec through its C API on one thread
// (threads = 1, as the WebAssembly decoder runs), median of 15 decodes per
// file, bytes already in memory. Build against the host library:
//
//   g++ -O2 -std=c++17 web/bench/native-decode.cpp -Icodec/include build/lib/libdrmcodec.a \
//       -llz4 -fopenmp -pthread -o web/build/native-decode
//   web/build/native-decode web/build/bench/*.drm
#include <drmcodec/drmcodec_c.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

int main(int argc, char** argv) {
    for (int a = 1; a < argc; ++a) {
        std::ifstream in(argv[a], std::ios::binary);
        const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::vector<double> ms;
        for (int run = 0; run < 15; ++run) {
            const auto start = std::chrono::steady_clock::now();
            drmcodec_decoded* decoded = drmcodec_decode(bytes.data(), bytes.size(), 1);
            const auto end = std::chrono::steady_clock::now();
            if (drmcodec_decoded_status(decoded) != DRMCODEC_OK) {
                std::fprintf(stderr, "%s: %s\n", argv[a], drmcodec_decoded_error(decoded));
                drmcodec_decoded_free(decoded);
                return 1;
            }
            drmcodec_decoded_free(decoded);
            ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        }
        std::sort(ms.begin(), ms.end());
        std::printf("%-40s %8.2f ms\n", argv[a], ms[ms.size() / 2]);
    }
    return 0;
}
