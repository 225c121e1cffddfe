// Many files at once for `drm encode`, `drm decode` and `drm verify`:
// inputs (files, or folders read in name order) are spread over worker
// threads, one file per worker at a time; each file's line is printed as it
// finishes, and one summary line at the end.
#ifndef DRM_TOOLS_BATCH_H
#define DRM_TOOLS_BATCH_H

#include "cli.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace drm {
namespace cli {

// The options a batch run adds to a command: -o/--output-dir DIR (valued),
// -j/--jobs N (valued).
const std::vector<std::string>& batchOptionNames();

// -j N or --jobs N (1..1024); without it, std::thread::hardware_concurrency()
// (at least 1). A malformed value is a UsageError.
int jobsFrom(const Arguments& args);

// The options each file of a batch encodes with: one thread per file where
// several files are coded at once (they already share the cores).
drm::EncodeOptions perFileOptions(const drm::EncodeOptions& options, int jobs, size_t files);

// Without -o: exactly IN and OUT, neither a folder. `what` names them for
// the messages ("an input mesh and an output .drm file"). UsageError
// otherwise.
void expectInputAndOutput(const Arguments& args, const std::string& command, const std::string& what);

// Files as given; each folder replaced by its regular files for which
// `wanted(name)` holds, sorted by name (not recursive). Throws drm::Error when
// a folder cannot be listed or the whole list is empty (`kinds` names what
// was looked for, e.g. ".ply, .obj, .off or .stl files").
std::vector<std::string> collectInputs(const std::vector<std::string>& paths,
                                       const std::function<bool(const std::string&)>& wanted, const std::string& kinds);

// DIR/STEM.EXTENSION for every input, DIR created if missing. Throws
// drm::Error if DIR is not a folder, if two inputs would write the same
// output (a/bunny.ply and b/bunny.obj), or if an output (or, for .obj, its
// .mtl) is one of the inputs, through links too: nothing is written then.
std::vector<std::string> outputPaths(const std::vector<std::string>& inputs, const std::string& dir,
                                     const std::string& extension);

// What one file gave.
struct FileOutcome {
    bool ok = false;
    uint64_t bytesOut = 0;           // written (or, for verify, encoded) bytes
    std::string line;                // the stdout line on success
    std::vector<std::string> notes;  // printed as "drm: note: INPUT: note"
    std::string error;               // the reason on failure, naming the file
};

struct BatchFile {
    std::string input;
    std::string output;  // empty for verify
    uint64_t bytesIn = 0;
};

// How the summary line speaks of a batch.
struct BatchWords {
    const char* done;      // "encoded"
    const char* outBytes;  // "bytes out"
    bool expands;          // ratio as "expansion 1:R" (decode), else "compression R:1"
};

// Runs `work` on every file with `jobs` threads (largest input first, for an
// even spread). As each file finishes: "[k/N] LINE" on stdout, its notes and
// its error ("drm: error: ...") on stderr. At the end one summary line on
// stdout, over the files that succeeded:
//   "encoded 4 of 5 files (1 failed): 812345 bytes in -> 81234 bytes out,
//    compression 10.00:1, 1.234 s wall, 2 jobs"
// Throws drm::Error("N of M files failed: a, b") when any failed: exit code 1.
void runBatch(const BatchWords& words, const std::vector<BatchFile>& files, int jobs,
              const std::function<FileOutcome(const BatchFile&)>& work);

// Size of a file in bytes, 0 if it cannot be read.
uint64_t fileBytes(const std::string& path);

// e.what() with the file named: prefixed by "INPUT: " unless it mentions it.
std::string namingFile(const std::string& input, const std::string& message);

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_BATCH_H
