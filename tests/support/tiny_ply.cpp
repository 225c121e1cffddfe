#include "tiny_ply.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace drm_test {
namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw std::runtime_error(path + ": " + why);
}

uint8_t readU8(std::istream& in, const std::string& path) {
    char byte;
    if (!in.get(byte)) refuse(path, "ends early");
    return uint8_t(byte);
}

uint32_t readU32(std::istream& in, const std::string& path) {
    uint32_t value = 0;
    for (int i = 0; i < 4; ++i) value |= uint32_t(readU8(in, path)) << (8 * i);
    return value;
}

float readF32(std::istream& in, const std::string& path) {
    const uint32_t bits = readU32(in, path);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

}  // namespace

drm::Mesh readTinyPly(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) refuse(path, "cannot be opened");
    // The header must be exactly this, up to the two counts.
    const std::vector<std::string> expected = {
        "ply", "format binary_little_endian 1.0", "element vertex #", "property float x", "property float y",
        "property float z", "element face #", "property list uchar int vertex_indices", "end_header"};
    size_t counts[2] = {0, 0};
    int countIndex = 0;
    for (const std::string& want : expected) {
        std::string line;
        do {
            if (!std::getline(in, line)) refuse(path, "header ends early");
            if (!line.empty() && line.back() == '\r') line.pop_back();
        } while (line.rfind("comment", 0) == 0 || line.rfind("obj_info", 0) == 0);
        const size_t hash = want.find('#');
        if (hash == std::string::npos) {
            if (line != want) refuse(path, "header line \"" + line + "\" is not \"" + want + "\"");
            continue;
        }
        if (line.compare(0, hash, want, 0, hash) != 0) refuse(path, "header line \"" + line + "\" is unexpected");
        std::istringstream number(line.substr(hash));
        if (!(number >> counts[countIndex++])) refuse(path, "bad element count in \"" + line + "\"");
    }
    drm::Mesh mesh;
    mesh.positions.resize(3 * counts[0]);
    for (float& x : mesh.positions) x = readF32(in, path);
    mesh.triangles.resize(3 * counts[1]);
    for (size_t f = 0; f < counts[1]; ++f) {
        if (readU8(in, path) != 3) refuse(path, "face " + std::to_string(f) + " is not a triangle");
        for (int k = 0; k < 3; ++k) mesh.triangles[3 * f + size_t(k)] = readU32(in, path);
    }
    return mesh;
}

std::vector<NamedMesh> readPlyDirectory(const std::string& dir) {
    std::vector<std::filesystem::path> paths;
    if (std::filesystem::is_directory(dir))
        for (const auto& entry : std::filesystem::directory_iterator(dir))
            if (entry.is_regular_file() && entry.path().extension() == ".ply") paths.push_back(entry.path());
    std::sort(paths.begin(), paths.end());
    std::vector<NamedMesh> meshes;
    for (const std::filesystem::path& p : paths) {
        try {
            meshes.push_back({p.stem().string(), readTinyPly(p.string())});
        } catch (const std::runtime_error&) {
            // Not the layout this reader knows (tests/data/bad holds such files on purpose).
        }
    }
    return meshes;
}

}  // namespace drm_test
