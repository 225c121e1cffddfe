// What every `drm` subcommand shares: argument parsing, usage errors, the
// progress bar, notes, and reading options into drm::EncodeOptions.
#ifndef DRM_TOOLS_CLI_H
#define DRM_TOOLS_CLI_H

#include <drmcodec/drmcodec.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace drm {
namespace cli {

// A mistake in how the command was called: exit code 2, not 1.
class UsageError : public std::runtime_error {
public:
    explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

// A command's arguments: positional ones in order, options by name.
struct Arguments {
    std::string command;
    std::vector<std::string> positional;
    std::map<std::string, std::string> options;  // "--bits" -> "12"; flags -> ""

    bool has(const std::string& option) const { return options.count(option) != 0; }
    std::string value(const std::string& option, const std::string& fallback = "") const;
    // Throws UsageError unless the positional count is within [min, max].
    void expectPositional(size_t min, size_t max, const std::string& what) const;
};

// Splits argv[first..] into positional arguments and options. `valued` lists
// options taking a value ("--bits 12" or "--bits=12"), `flags` options
// without one. Anything else starting with "--" is a UsageError.
Arguments parseArguments(const std::string& command, const std::vector<std::string>& args,
                         const std::vector<std::string>& valued, const std::vector<std::string>& flags);

// --bits, --predictor, --curvature, --geometry, --levers, --keep-vertex-order,
// --attributes, --normal-bits, --uv-bits, --weld as given (defaults otherwise).
// Malformed values are UsageErrors; ranges are left to the codec.
drm::EncodeOptions encodeOptionsFrom(const Arguments& args);

// The options encodeOptionsFrom reads, for parseArguments: those taking a
// value, and flags (--keep-vertex-order).
const std::vector<std::string>& encodeOptionNames();
const std::vector<std::string>& encodeFlagNames();
// --index auto|grid|flann (encode and decode): which spatial index runs the
// neighbour searches; never changes a file or a decoded mesh.
drm::NeighbourIndex neighbourIndexFrom(const Arguments& args);
// A whole-number option's value; throws UsageError naming it otherwise.
int wholeNumberOption(const Arguments& args, const char* name);

// Notes for what `mesh` carries among the attributes `options` asks for
// that the encoded file does not hold (no section in stats), e.g. "the
// file's normals are not kept in .drm files"; empty when all are kept.
std::vector<std::string> attributesNotKept(const drm::Mesh& mesh, const drm::EncodeOptions& options,
                                           const drm::Stats& stats);

// The attribute sections of a file as "normals 1234 bytes (4.56 bits per
// vertex), ..." or "" for none.
std::string attributeSummary(const drm::Stats& stats);

// "drm: note: ..." on stderr.
void printNote(const std::string& note);

// One mesh encoded on two threads: both allocate from the main heap, where
// huge_pages.cpp's advice covers the blocks. Call before any thread starts;
// not for batches, whose workers would then queue for one lock.
void shareOneMallocArena();

// For one mesh of more than 2^18 vertices (`drm encode` of a single file),
// blocks of 1 MiB and more are mapped on their own and given back when
// freed, instead of carved from the heap that main.cpp keeps. Up to 2^22
// vertices the encoder codes the connectivity beside the vertex set, two
// threads filling one heap, and their tables, interleaved, leave holes the
// heap cannot reuse: the peak then varies from run to run, and mapping
// large blocks apart lowers it in the same time; larger meshes, coded one
// stage after the other, peak lower too (docs/tuning.md, "The drm tool").
// A batch keeps main.cpp's setting, which is process-wide: its small files
// gain from the heap's reuse.
void mapLargeBlocksApart(size_t vertexCount);

// A one-line progress bar on stderr, drawn only when stderr is a terminal.
// Cleared when finished or destroyed (also while an exception unwinds).
class ProgressBar {
public:
    explicit ProgressBar(const std::string& label);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    drm::Progress callback();
    void setLabel(const std::string& label) { label_ = label; }
    void clear();

private:
    void draw(double fraction, const char* stage);

    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    int lastPermille_ = -1;
};

// "12.345" with a fixed number of decimals.
std::string fixed(double value, int decimals);

// The last path component without its extension ("a/b/bunny.ply" -> "bunny").
std::string fileStem(const std::string& path);
std::string fileName(const std::string& path);
bool hasExtension(const std::string& path, const std::string& extension);  // case-insensitive

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_CLI_H
