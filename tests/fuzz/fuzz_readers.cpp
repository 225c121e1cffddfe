// libFuzzer target for the mesh file readers (PLY, OBJ with its material
// library, OFF, STL): any bytes must load or be refused with drm::Error,
// never crash, hang, read out of bounds or allocate without bound. A mesh
// that loads is also encoded and decoded, so what a reader hands on is
// something the codec accepts or refuses cleanly.
//
// Input: one byte choosing the format, then the file's bytes. For OBJ, a
// 0xFF byte splits the input into the OBJ and its library "m.mtl".
#include <drmcodec/drmcodec.h>
#include <drm_vcg/mesh_io.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace {

const std::string& scratchFolder() {
    static const std::string folder = [] {
        char pattern[] = "/tmp/drm-fuzz-readers-XXXXXX";
        const char* made = ::mkdtemp(pattern);
        if (!made) std::abort();
        return std::string(made);
    }();
    return folder;
}

void writeFile(const std::string& path, const uint8_t* data, size_t size) {
    FILE* out = std::fopen(path.c_str(), "wb");
    if (!out) std::abort();
    if (size > 0 && std::fwrite(data, 1, size, out) != size) std::abort();
    std::fclose(out);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    static const char* const kExtensions[] = {".ply", ".obj", ".off", ".stl"};
    const std::string path = scratchFolder() + "/m" + kExtensions[data[0] % 4];
    const uint8_t* body = data + 1;
    size_t bodySize = size - 1;
    const std::string library = scratchFolder() + "/m.mtl";
    ::unlink(library.c_str());
    if (data[0] % 4 == 1) {
        for (size_t i = 0; i < bodySize; ++i)
            if (body[i] == 0xFF) {
                writeFile(library, body + i + 1, bodySize - i - 1);
                bodySize = i;
                break;
            }
    }
    writeFile(path, body, bodySize);
    try {
        const drm::vcgio::LoadedMesh loaded = drm::vcgio::loadMesh(path);
        if (loaded.mesh.vertexCount() > 4096 || loaded.mesh.faceCount() > 4096) return 0;
        drm::EncodeOptions options;
        options.threads = 1;
        const drm::Encoded encoded = drm::encode(loaded.mesh, options);
        drm::DecodeOptions decodeOptions;
        decodeOptions.threads = 1;
        drm::decode(encoded.bytes.data(), encoded.bytes.size(), decodeOptions);
    } catch (const drm::Error&) {
    }
    ::unlink(path.c_str());
    return 0;
}
