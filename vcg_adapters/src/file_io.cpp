// Whole-file reads and atomic writes (see drm_vcg/file_io.h).
#include "drm_vcg/file_io.h"

#include <drmcodec/drmcodec.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>
#include <cstdlib>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace drm {
namespace vcgio {

namespace {

std::string systemReason() { return std::strerror(errno); }

std::string folderOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

// The file a chain of symbolic links ends at (PATH itself if it is none),
// which need not exist yet: a dangling link names the file to create.
std::string linkTarget(const std::string& path) {
    std::string current = path;
    for (int hops = 0; hops < 40; ++hops) {
        struct stat info;
        if (::lstat(current.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return current;
        std::vector<char> buffer(size_t(info.st_size > 0 ? info.st_size : 255) + 1);
        const ssize_t n = ::readlink(current.c_str(), buffer.data(), buffer.size());
        if (n < 0) throw Error(ErrorKind::Io, "cannot write " + path + ": " + systemReason());
        if (size_t(n) >= buffer.size()) throw Error(ErrorKind::Io, "cannot write " + path + ": the link changed while read");
        const std::string to(buffer.data(), size_t(n));
        current = (!to.empty() && to[0] == '/') ? to : folderOf(current) + "/" + to;
    }
    throw Error(ErrorKind::Io, "cannot write " + path + ": too many levels of symbolic links");
}

// The writer's bytes go to the temporary file through a 64 KB buffer, not
// into a string of the whole file first: a 1M-triangle PLY held that way
// cost about 100 bytes per vertex at the decoder's peak (a string grown by
// doubling, then its copy).
class FileDescriptorBuffer : public std::streambuf {
public:
    explicit FileDescriptorBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
    int error() const { return error_; }  // errno of the first failed write, else 0

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        if (n <= epptr() - pptr()) {
            std::memcpy(pptr(), s, size_t(n));
            pbump(int(n));
            return n;
        }
        if (!drain() || !writeAll(s, size_t(n))) return 0;
        return n;
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain() {
        const bool ok = writeAll(pbase(), size_t(pptr() - pbase()));
        setp(buffer_, buffer_ + sizeof buffer_);
        return ok;
    }
    bool writeAll(const char* data, size_t size) {
        if (error_ != 0) return false;
        for (size_t done = 0; done < size;) {
            const ssize_t n = ::write(fd_, data + done, size - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                error_ = n < 0 ? errno : EIO;
                return false;
            }
            done += size_t(n);
        }
        return true;
    }

    int fd_;
    int error_ = 0;
    char buffer_[1 << 16];
};

}  // namespace

namespace {

// A file written in full under a temporary name beside its target, not yet
// renamed over it.
struct PreparedFile {
    std::string target, temporary, shown;
};

// Everything of writeFileAtomically but the rename: checks, the temporary
// file, its content, mode and owner, fsync.
PreparedFile prepareFile(const std::string& path, const std::function<void(std::ostream&)>& write) {
    // A symbolic link is written through: its target gets the new content
    // and the link stays a link (as an editor saving through it would).
    const std::string target = linkTarget(path);
    const std::string shown = target == path ? path : path + " (a link to " + target + ")";
    struct stat existing;
    const bool replacing = ::stat(target.c_str(), &existing) == 0;
    if (replacing) {
        if (S_ISDIR(existing.st_mode)) throw Error(ErrorKind::Io, "cannot write " + shown + ": it is a directory");
        if (!S_ISREG(existing.st_mode)) throw Error(ErrorKind::Io, "cannot write " + shown + ": not a regular file");
        // The folder may let us rename over a file we may not write (mode
        // 444): refuse, as MeshLab's own exporters and most editors do.
        if (::access(target.c_str(), W_OK) != 0)
            throw Error(ErrorKind::Io, "cannot write " + shown + ": " +
                        (errno == EACCES || errno == EPERM || errno == EROFS
                             ? std::string("the file is read-only for you (") + systemReason() + ")"
                             : systemReason()));
    }

    // mkstemp creates a new file with a random name, exclusively: it never
    // follows a symlink or reuses a file someone else put there, and only
    // the file it created is ever removed.
    std::string temporary = target + ".tmp.XXXXXX";
    const int fd = ::mkstemp(&temporary[0]);
    if (fd < 0) {
        // The new file is made in the target's folder: when that is what
        // refuses, say so (the file itself may well be writable).
        if (errno == EACCES || errno == EPERM || errno == EROFS) {
            const std::string reason = systemReason();
            const size_t slash = target.rfind('/');
            const std::string folder = slash == std::string::npos ? "." : (slash == 0 ? "/" : target.substr(0, slash));
            throw Error(ErrorKind::Io, "cannot write " + shown + ": the folder " + folder +
                                           " does not let you create files in it (" + reason + ")");
        }
        throw Error(ErrorKind::Io, "cannot write " + shown + ": " + systemReason());
    }
    auto fail = [&](const std::string& reason) {
        ::close(fd);
        ::unlink(temporary.c_str());
        throw Error(ErrorKind::Io, "cannot write " + shown + ": " + reason);
    };
    if (replacing) {
        // The new file takes the old one's owner (only root may give a file
        // away; a user may keep its group if they belong to it) and mode, so
        // a private file stays private. Set-id bits are kept only when the
        // owner is, and chmod comes after chown, which clears them.
        bool sameOwner = ::fchown(fd, existing.st_uid, existing.st_gid) == 0;
        if (!sameOwner) {
            struct stat created;
            if (::fchown(fd, uid_t(-1), existing.st_gid) != 0) { /* the group stays ours */ }
            sameOwner = ::fstat(fd, &created) == 0 && created.st_uid == existing.st_uid &&
                        created.st_gid == existing.st_gid;
        }
        const mode_t mode = existing.st_mode & (sameOwner ? mode_t(07777) : mode_t(01777));
        if (::fchmod(fd, mode) != 0) fail(systemReason());
    } else {
        const mode_t mask = ::umask(0);
        ::umask(mask);
        if (::fchmod(fd, 0666 & ~mask) != 0) fail(systemReason());  // mkstemp's 0600 is too private for a mesh
    }
    // The content goes to the temporary file as it is produced; a writer
    // that fails takes the temporary file with it, so the target is never
    // touched.
    {
        FileDescriptorBuffer buffer(fd);
        std::ostream content(&buffer);
        try {
            write(content);
        } catch (...) {
            ::close(fd);
            ::unlink(temporary.c_str());
            throw;
        }
        content.flush();
        if (buffer.error() != 0) fail(std::strerror(buffer.error()));
        if (!content) fail("the output could not be produced");
    }
    if (::fsync(fd) != 0) fail(systemReason());
    if (::close(fd) != 0) {
        ::unlink(temporary.c_str());
        throw Error(ErrorKind::Io, "cannot write " + shown + ": " + systemReason());
    }
    return PreparedFile{target, temporary, shown};
}

// Renames a prepared file over its target and syncs the folder.
void commitFile(const PreparedFile& file) {
    if (std::rename(file.temporary.c_str(), file.target.c_str()) != 0) {
        const std::string reason = systemReason();
        ::unlink(file.temporary.c_str());
        throw Error(ErrorKind::Io, "cannot write " + file.shown + ": " + reason);
    }
    // The rename lives in the folder: sync it too, or a crash soon after
    // can bring back the old file (or none). The new file is in place by
    // now, so only a real I/O error is reported.
    const int folder = ::open(folderOf(file.target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder >= 0) {
        const bool failed = ::fsync(folder) != 0 && errno == EIO;
        ::close(folder);
        if (failed) throw Error(ErrorKind::Io, "cannot write " + file.shown + ": the folder could not be synced (I/O error)");
    }
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    commitFile(prepareFile(path, write));
}

void writeFilesAtomically(const std::vector<std::pair<std::string, std::vector<uint8_t>>>& files) {
    std::vector<PreparedFile> prepared;
    try {
        for (const auto& file : files)
            prepared.push_back(prepareFile(file.first, [&file](std::ostream& out) {
                out.write(reinterpret_cast<const char*>(file.second.data()), std::streamsize(file.second.size()));
            }));
    } catch (...) {
        for (const PreparedFile& done : prepared) ::unlink(done.temporary.c_str());
        throw;
    }
    for (size_t i = 0; i < prepared.size(); ++i) {
        try {
            commitFile(prepared[i]);
        } catch (...) {
            for (size_t j = i + 1; j < prepared.size(); ++j) ::unlink(prepared[j].temporary.c_str());
            throw;
        }
    }
}

void writeFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes) {
    writeFileAtomically(path, [&bytes](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    });
}

void refuseOverwritingInput(const std::string& input, const std::string& output) {
    struct stat in, out;
    if (::stat(input.c_str(), &in) != 0 || ::stat(output.c_str(), &out) != 0) return;
    if (in.st_dev == out.st_dev && in.st_ino == out.st_ino)
        throw Error(ErrorKind::InvalidInput, "cannot write " + output + ": it is the input " + input +
                    (output == input ? "" : " (the same file)") + ", which would be replaced");
}

std::vector<uint8_t> readFileBytes(const std::string& path) {
    struct stat info;
    if (::stat(path.c_str(), &info) != 0) throw Error(ErrorKind::Io, "cannot read " + path + ": " + systemReason());
    if (!S_ISREG(info.st_mode)) throw Error(ErrorKind::Io, "cannot read " + path + ": not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::Io, "cannot read " + path + ": " + systemReason());
    std::vector<uint8_t> bytes(size_t(info.st_size));
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
    if (in.gcount() != std::streamsize(bytes.size()))
        throw Error(ErrorKind::Io, "cannot read " + path + ": read " + std::to_string(in.gcount()) + " of " +
                    std::to_string(bytes.size()) + " bytes");
    return bytes;
}

}  // namespace vcgio
}  // namespace drm
