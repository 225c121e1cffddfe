// Whole-file reads and atomic writes (see drm_vcg/file_io.h).
#include "drm_vcg/file_io.h"

#include <drm/drm.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace drm {
namespace vcgio {

namespace {

std::string systemReason() { return std::strerror(errno); }

}  // namespace

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    struct stat existing;
    if (::stat(path.c_str(), &existing) == 0 && S_ISDIR(existing.st_mode))
        throw Error("cannot write " + path + ": it is a directory");

    const std::string temporary = path + ".tmp." + std::to_string(::getpid());
    try {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("cannot write " + path + ": " + systemReason());
        write(out);
        out.flush();
        if (!out) throw Error("cannot write " + path + ": " + systemReason());
        out.close();
        if (out.fail()) throw Error("cannot write " + path + ": " + systemReason());
        if (std::rename(temporary.c_str(), path.c_str()) != 0)
            throw Error("cannot write " + path + ": " + systemReason());
    } catch (...) {
        std::remove(temporary.c_str());
        throw;
    }
}

void writeFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes) {
    writeFileAtomically(path, [&bytes](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    });
}

std::vector<uint8_t> readFileBytes(const std::string& path) {
    struct stat info;
    if (::stat(path.c_str(), &info) != 0) throw Error("cannot read " + path + ": " + systemReason());
    if (!S_ISREG(info.st_mode)) throw Error("cannot read " + path + ": not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot read " + path + ": " + systemReason());
    std::vector<uint8_t> bytes(size_t(info.st_size));
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
    if (in.gcount() != std::streamsize(bytes.size()))
        throw Error("cannot read " + path + ": read " + std::to_string(in.gcount()) + " of " +
                    std::to_string(bytes.size()) + " bytes");
    return bytes;
}

}  // namespace vcgio
}  // namespace drm
