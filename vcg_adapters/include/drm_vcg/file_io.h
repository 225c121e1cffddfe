// Whole-file reads, and writes that appear complete or not at all.
//
// Output is produced in memory, then written to a new file `PATH.tmp.XXXXXX`
// created exclusively with a random name in the same folder (same file
// system, so the final rename is atomic), synced, and renamed over PATH.
// Only that file is ever removed on failure: a failed write never leaves a
// partial file, never follows a planted symlink, and never touches an
// existing file.
// Shared by savePly and the `drm` tool's .drm output. C++14-clean.
#ifndef DRM_VCG_FILE_IO_H
#define DRM_VCG_FILE_IO_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace drm {
namespace vcgio {

// Calls write(stream) on a temporary file next to `path`, then renames it to
// `path`. Throws drm::Error("cannot write PATH: reason") on failure, and
// passes on what `write` throws; either way the temporary file is removed.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

void writeFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes);

// Reads a whole file. Throws drm::Error("cannot read PATH: reason").
std::vector<uint8_t> readFileBytes(const std::string& path);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_FILE_IO_H
