// Whole-file reads, and writes that appear complete or not at all.
//
// Output is produced in memory, then written to a new file `PATH.tmp.XXXXXX`
// created exclusively with a random name in the same folder (same file
// system, so the final rename is atomic), synced, renamed over PATH, and the
// folder synced. Only that file is ever removed on failure: a failed write
// never leaves a partial file, never follows a planted symlink, and never
// touches an existing file.
// Replacing a file keeps what the user set on it: its mode (a 600 file stays
// 600) and its owner and group where the system allows it (only root may
// give a file away). A symbolic link PATH is written through: its target is
// replaced and the link stays. A file the user may not write (mode 444, say)
// is refused, even in a folder they may write, as MeshLab's own exporters do.
// Shared by savePly and the `drm` tool's .drm output. C++14-clean.
#ifndef DRM_VCG_FILE_IO_H
#define DRM_VCG_FILE_IO_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace drm {
namespace vcgio {

// Calls write(stream) on a temporary file next to `path` (next to the link's
// target if `path` is a symbolic link), then renames it over that file. Throws drm::Error("cannot write PATH: reason") on failure, and
// passes on what `write` throws; either way the temporary file is removed.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

void writeFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes);

// Several files that belong together (an OBJ and its library): each is
// written in full under its temporary name first, and only when all are
// complete are they renamed over their targets, so a failure before that
// leaves every existing file as it was.
void writeFilesAtomically(const std::vector<std::pair<std::string, std::vector<uint8_t>>>& files);

// Throws drm::Error("cannot write OUTPUT: it is the input INPUT") when
// `output` names the same file as `input` (the same path, a link to it or a
// hard link): writing there would replace the input. Paths that do not
// exist yet name no input.
void refuseOverwritingInput(const std::string& input, const std::string& output);

// Reads a whole file. Throws drm::Error("cannot read PATH: reason").
std::vector<uint8_t> readFileBytes(const std::string& path);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_FILE_IO_H
