// Whole-file reads and atomic writes (see drm_vcg/file_io.h).
#include "drm_vcg/file_io.h"

#include <drm/drm.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <cstdlib>
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

    // The content is produced first, so a failing writer touches no file.
    std::ostringstream content(std::ios::binary);
    write(content);
    if (!content) throw Error("cannot write " + path + ": the output could not be produced");
    const std::string bytes = content.str();

    // mkstemp creates a new file with a random name, exclusively: it never
    // follows a symlink or reuses a file someone else put there, and only
    // the file it created is ever removed.
    std::string temporary = path + ".tmp.XXXXXX";
    const int fd = ::mkstemp(&temporary[0]);
    if (fd < 0) throw Error("cannot write " + path + ": " + systemReason());
    auto fail = [&](const std::string& reason) {
        ::close(fd);
        ::unlink(temporary.c_str());
        throw Error("cannot write " + path + ": " + reason);
    };
    const mode_t mask = ::umask(0);
    ::umask(mask);
    if (::fchmod(fd, 0666 & ~mask) != 0) fail(systemReason());  // mkstemp's 0600 is too private for a mesh
    for (size_t done = 0; done < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail(systemReason());
        done += size_t(n);
    }
    if (::fsync(fd) != 0) fail(systemReason());
    if (::close(fd) != 0) {
        ::unlink(temporary.c_str());
        throw Error("cannot write " + path + ": " + systemReason());
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string reason = systemReason();
        ::unlink(temporary.c_str());
        throw Error("cannot write " + path + ": " + reason);
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
