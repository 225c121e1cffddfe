// Writes the fuzzer's seed corpus: every small test mesh (tests/support, and
// the tests/data PLY files if given) encoded with every option set, one .drm
// file each, so the fuzzer starts from valid files that reach each decoder
// branch. Generated at build time rather than committed, so the seeds follow
// the current file format.
//
// usage: make_seeds OUTPUT_DIR [--ply-dir DIR] [--max-bytes N]
//   Files over N bytes (default 4096, the fuzzer's -max_len) are left out.
//   A mesh that does not survive encode + decode is reported on stderr and
//   left out; the robustness tests fail on the same cases.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "drmcodec/drmcodec.h"
#include "option_sets.h"
#include "test_meshes.h"
#include "tiny_ply.h"

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s OUTPUT_DIR [--ply-dir DIR] [--max-bytes N]\n", argv[0]);
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    std::vector<drm_test::NamedMesh> meshes = drm_test::smallMeshes();
    size_t maxBytes = 4096;
    for (int i = 2; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--ply-dir") == 0) {
            for (drm_test::NamedMesh& m : drm_test::readPlyDirectory(argv[i + 1])) meshes.push_back(std::move(m));
        } else if (std::strcmp(argv[i], "--max-bytes") == 0) {
            maxBytes = size_t(std::strtoull(argv[i + 1], nullptr, 10));
        } else {
            std::fprintf(stderr, "unknown option %s\n", argv[i]);
            return 2;
        }
    }
    // Seeds of option sets or meshes that no longer exist must not linger.
    std::filesystem::create_directories(dir);
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.path().extension() == ".drm") std::filesystem::remove(entry.path());
    int written = 0, tooLarge = 0, failed = 0;
    for (const drm_test::NamedMesh& mesh : meshes)
        for (const drm_test::NamedOptions& options : drm_test::optionSets()) {
            const std::string name = mesh.name + "." + options.name;
            try {
                // One thread: in this instrumented build the threads share
                // the coverage counters, and two of them took make_seeds
                // from about 4.5 to 10 minutes in CI (the files are the
                // same either way).
                drm::EncodeOptions oneThread = options.options;
                oneThread.threads = 1;
                const drm::Encoded encoded = drm::encode(mesh.mesh, oneThread);
                if (encoded.bytes.size() > maxBytes) {
                    ++tooLarge;
                    continue;
                }
                drm::decode(encoded.bytes);
                std::ofstream out(dir / (name + ".drm"), std::ios::binary);
                out.write(reinterpret_cast<const char*>(encoded.bytes.data()), std::streamsize(encoded.bytes.size()));
                ++written;
            } catch (const drm::Error& e) {
                std::fprintf(stderr, "left out %s (codec bug?): %s\n", name.c_str(), e.what());
                ++failed;
            }
        }
    std::printf("%d seeds written to %s; %d over %zu bytes and %d that failed to round-trip left out\n", written,
                dir.string().c_str(), tooLarge, maxBytes, failed);
    return 0;
}
