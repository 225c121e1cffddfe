// Encodes and decodes meshes built in code with many option sets and prints,
// for each, the size and an FNV-1a hash of the .drm bytes and of the decoded
// mesh. check_cross_build.sh builds this with several compilers and
// optimization levels: a file must not depend on which build wrote it, and
// a decode must not depend on which build read it, so every build has to
// print the same lines.
//
// usage: encode_decode_dump [--ply-dir DIR] [--write DIR]
//          one line per mesh and option set; --ply-dir adds the meshes of
//          tests/data, --write also writes the files (DIR/<mesh>.<options>.drm)
//        encode_decode_dump --decode FILE...
//          the decoded-mesh hash of each file, to decode one build's files
//          with another build
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "option_sets.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace {

class Fnv1a {
public:
    void add(const void* data, size_t size) {
        const uint8_t* bytes = static_cast<const uint8_t*>(data);
        for (size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 0x100000001B3ull;
    }
    template <class T>
    void addAll(const std::vector<T>& values) {
        add(values.data(), values.size() * sizeof(T));
    }
    uint64_t value() const { return hash_; }

private:
    uint64_t hash_ = 0xCBF29CE484222325ull;
};

// Larger meshes than the seeds use: enough candidates per edge that the
// predictors, gap closing and angle order all make real decisions.
std::vector<drm_test::NamedMesh> largerMeshes() {
    drm::Mesh combined = drm_test::append(drm_test::gridPatch(24, true, 0.2, 5), drm_test::icosphere(2), 0.5f, 0.5f, 1.5f);
    drm_test::addVertex(combined, 3, 3, 3);
    return {{"icosphere4", drm_test::icosphere(4)},
            {"jittered-grid40", drm_test::gridPatch(40, true, 0.24, 3)},
            {"box-ring9", drm_test::boxRing(9)},
            {"combined", combined}};
}

bool isLargeMeshOption(const std::string& name) {
    for (const char* n : {"default", "bits21", "raw-bits21-parallelogram", "midpoint-curvature", "no-levers",
                          "keep-order-bits12-try-without", "bits4"})
        if (name == n) return true;
    return false;
}

std::string hex(uint64_t value) {
    char text[20];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

uint64_t meshHash(const drm::Mesh& mesh) {
    Fnv1a hash;
    hash.addAll(mesh.positions);  // float bit patterns: x86-64 floats are IEEE, little-endian
    hash.addAll(mesh.triangles);
    return hash.value();
}

uint64_t decodedHash(const drm::Decoded& decoded) {
    Fnv1a hash;
    const uint64_t mesh = meshHash(decoded.mesh);
    hash.add(&mesh, sizeof mesh);
    hash.addAll(decoded.quantized);
    return hash.value();
}

// The input's hash is printed too: if it differs between builds, the test
// meshes, not the codec, depend on the build.
void dump(const std::string& mesh, const drm::Mesh& input, const drm_test::NamedOptions& options,
          const std::string& writeDir, Fnv1a& all) {
    std::string line = mesh + " " + options.name + " input=" + hex(meshHash(input)) + " ";
    try {
        const drm::Encoded encoded = drm::encode(input, options.options);
        Fnv1a fileHash;
        fileHash.addAll(encoded.bytes);
        if (!writeDir.empty()) {
            std::ofstream out(writeDir + "/" + mesh + "." + options.name + ".drm", std::ios::binary);
            out.write(reinterpret_cast<const char*>(encoded.bytes.data()), std::streamsize(encoded.bytes.size()));
        }
        const drm::Decoded decoded = drm::decode(encoded.bytes);
        line += "bytes=" + std::to_string(encoded.bytes.size()) + " file=" + hex(fileHash.value()) +
                " decoded=" + hex(decodedHash(decoded)) + " faces=" + std::to_string(decoded.mesh.faceCount());
    } catch (const drm::Error& e) {
        line += std::string("error: ") + e.what();
    }
    std::printf("%s\n", line.c_str());
    all.add(line.data(), line.size());
}

int decodeFiles(int count, char** paths) {
    for (int i = 0; i < count; ++i) {
        std::ifstream in(paths[i], std::ios::binary);
        const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::string line = paths[i];
        try {
            line += " decoded=" + hex(decodedHash(drm::decode(bytes)));
        } catch (const drm::Error& e) {
            line += std::string(" error: ") + e.what();
        }
        std::printf("%s\n", line.c_str());
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && std::strcmp(argv[1], "--decode") == 0) return decodeFiles(argc - 2, argv + 2);
    std::string writeDir, plyDir;
    for (int i = 1; i < argc; i += 2) {
        if (i + 1 < argc && std::strcmp(argv[i], "--write") == 0) {
            writeDir = argv[i + 1];
        } else if (i + 1 < argc && std::strcmp(argv[i], "--ply-dir") == 0) {
            plyDir = argv[i + 1];
        } else {
            std::fprintf(stderr, "usage: %s [--ply-dir DIR] [--write DIR] | --decode FILE...\n", argv[0]);
            return 2;
        }
    }
    std::vector<drm_test::NamedMesh> larger = largerMeshes();
    if (!plyDir.empty())
        for (drm_test::NamedMesh& m : drm_test::readPlyDirectory(plyDir)) larger.push_back(std::move(m));
    Fnv1a all;
    for (const drm_test::NamedMesh& m : drm_test::smallMeshes())
        for (const drm_test::NamedOptions& o : drm_test::optionSets()) dump(m.name, m.mesh, o, writeDir, all);
    for (const drm_test::NamedMesh& m : larger)
        for (const drm_test::NamedOptions& o : drm_test::optionSets())
            if (isLargeMeshOption(o.name)) dump(m.name, m.mesh, o, writeDir, all);
    std::printf("all %016llx\n", static_cast<unsigned long long>(all.value()));
    return 0;
}
