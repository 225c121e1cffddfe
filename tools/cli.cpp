// Shared command-line helpers (see cli.h).
#include "cli.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace drm {
namespace cli {

std::string Arguments::value(const std::string& option, const std::string& fallback) const {
    auto it = options.find(option);
    return it == options.end() ? fallback : it->second;
}

void Arguments::expectPositional(size_t min, size_t max, const std::string& what) const {
    if (positional.size() < min)
        throw UsageError("'" + command + "' needs " + what + " (see 'drm help " + command + "')");
    if (positional.size() > max)
        throw UsageError("'" + command + "' takes " + what + ", but got an extra argument '" +
                         positional[max] + "' (see 'drm help " + command + "')");
}

Arguments parseArguments(const std::string& command, const std::vector<std::string>& args,
                         const std::vector<std::string>& valued, const std::vector<std::string>& flags) {
    Arguments parsed;
    parsed.command = command;
    auto listed = [](const std::vector<std::string>& names, const std::string& name) {
        return std::find(names.begin(), names.end(), name) != names.end();
    };
    bool onlyPositional = false;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (onlyPositional || arg.size() < 2 || arg[0] != '-') {
            parsed.positional.push_back(arg);
            continue;
        }
        if (arg == "--") {
            onlyPositional = true;
            continue;
        }
        const size_t equals = arg.find('=');
        const std::string name = arg.substr(0, equals);
        if (listed(valued, name)) {
            if (equals != std::string::npos) {
                parsed.options[name] = arg.substr(equals + 1);
            } else {
                if (i + 1 == args.size()) throw UsageError("option " + name + " needs a value");
                parsed.options[name] = args[++i];
            }
        } else if (listed(flags, name) && equals == std::string::npos) {
            parsed.options[name] = "";
        } else {
            throw UsageError("unknown option '" + arg + "' for '" + command + "' (see 'drm help " + command + "')");
        }
    }
    return parsed;
}

const std::vector<std::string>& encodeOptionNames() {
    static const std::vector<std::string> names = {"--bits", "--predictor", "--curvature", "--geometry", "--levers",
                                                   "--refine-bits", "--attributes", "--normal-bits", "--uv-bits",
                                                   "--weld", "--index", "--start", "--threads", "--parts",
                                                   "--connectivity"};
    return names;
}

const std::vector<std::string>& encodeFlagNames() {
    static const std::vector<std::string> names = {"--keep-vertex-order", "--verify"};
    return names;
}

int wholeNumberOption(const Arguments& args, const char* name) {
    const std::string text = args.value(name);
    errno = 0;
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || value < -1000000 || value > 1000000)
        throw UsageError(std::string(name) + " needs a whole number, not '" + text + "'");
    return int(value);
}

drm::NeighbourIndex neighbourIndexFrom(const Arguments& args) {
    if (!args.has("--index")) return drm::NeighbourIndex::Auto;
    const std::string name = args.value("--index");
    if (name == "auto") return drm::NeighbourIndex::Auto;
    if (name == "grid") return drm::NeighbourIndex::Grid;
    if (name == "flann") return drm::NeighbourIndex::Flann;
    throw UsageError("--index takes auto, grid or flann, not '" + name + "'");
}

drm::EncodeOptions encodeOptionsFrom(const Arguments& args) {
    drm::EncodeOptions options;
    options.index = neighbourIndexFrom(args);
    options.keepVertexOrder = args.has("--keep-vertex-order");
    options.verify = args.has("--verify");
    if (args.has("--bits")) options.bits = wholeNumberOption(args, "--bits");
    if (args.has("--refine-bits")) options.refineBits = wholeNumberOption(args, "--refine-bits");
    if (args.has("--normal-bits")) options.normalBits = wholeNumberOption(args, "--normal-bits");
    if (args.has("--uv-bits")) options.uvBits = wholeNumberOption(args, "--uv-bits");
    if (args.has("--weld")) {
        const std::string weld = args.value("--weld");
        if (weld == "auto") options.weld = drm::EncodeOptions::Weld::Auto;
        else if (weld == "on") options.weld = drm::EncodeOptions::Weld::On;
        else if (weld == "off") options.weld = drm::EncodeOptions::Weld::Off;
        else throw UsageError("--weld takes auto, on or off, not '" + weld + "'");
    }
    try {
        if (args.has("--predictor")) options.predictor = drm::parsePredictor(args.value("--predictor"));
        if (args.has("--attributes")) options.attributes = drm::parseAttributes(args.value("--attributes"));
        if (args.has("--geometry")) options.geometry = drm::parseGeometryCoder(args.value("--geometry"));
        if (args.has("--connectivity")) options.connectivity = drm::parseConnectivityCoder(args.value("--connectivity"));
        if (args.has("--levers")) {
            // Named levers are used as given: no automatic fallback to none.
            options.levers = drm::parseLevers(args.value("--levers"));
            options.tryWithoutLevers = false;
        }
    } catch (const drm::Error& e) {
        throw UsageError(e.what());
    }
    if (args.has("--start")) {
        const std::string start = args.value("--start");
        if (start != "search" && start != "smallest") throw UsageError("--start takes search or smallest, not '" + start + "'");
        options.searchStarts = start == "search";
    }
    if (args.has("--threads")) {
        options.threads = wholeNumberOption(args, "--threads");
        if (options.threads < 1 || options.threads > 2) throw UsageError("--threads takes 1 or 2");
    }
    if (args.has("--parts")) {
        const std::string parts = args.value("--parts");
        if (parts == "auto") options.connectivityParts = 0;
        else if (parts == "1") options.connectivityParts = 1;
        else if (parts == "2") options.connectivityParts = 2;
        else throw UsageError("--parts takes auto, 1 or 2, not '" + parts + "'");
    }
    if (args.has("--curvature")) {
        const std::string onOff = args.value("--curvature");
        if (onOff != "on" && onOff != "off") throw UsageError("--curvature takes on or off, not '" + onOff + "'");
        options.curvature = onOff == "on";
    }
    return options;
}

std::vector<std::string> attributesNotKept(const drm::Mesh& mesh, const drm::EncodeOptions& options,
                                           const drm::Stats& stats) {
    uint32_t kept = 0;
    for (const drm::Stats::AttributeSize& section : stats.attributeSizes) kept |= drm::sectionAttributes(section.name);
    const uint32_t lost = drm::attributesOf(mesh) & options.attributes & ~kept;
    if (lost == 0) return {};
    std::string names = drm::attributesName(lost);
    for (char& c : names)
        if (c == ',') c = ' ';
    std::string list;
    size_t start = 0;
    std::vector<std::string> words;
    while (start < names.size()) {
        const size_t space = std::min(names.find(' ', start), names.size());
        words.push_back(names.substr(start, space - start));
        start = space + 1;
    }
    for (size_t i = 0; i < words.size(); ++i) list += (i == 0 ? "" : i + 1 == words.size() ? " and " : ", ") + words[i];
    return {"the mesh's " + list + " are not kept in the .drm file (this codec build has no section for them)"};
}

std::string attributeSummary(const drm::Stats& stats) {
    std::string out;
    for (const drm::Stats::AttributeSize& section : stats.attributeSizes) {
        const double bpv = stats.vertices ? 8.0 * double(section.bytes) / double(stats.vertices) : 0.0;
        out += (out.empty() ? "" : ", ") + section.name + " " + std::to_string(section.bytes) + " bytes (" +
               fixed(bpv, 2) + " bits per vertex)";
    }
    return out;
}

void printNote(const std::string& note) { std::fprintf(stderr, "drm: note: %s\n", note.c_str()); }

ProgressBar::ProgressBar(const std::string& label) : label_(label), enabled_(::isatty(STDERR_FILENO) == 1) {}

ProgressBar::~ProgressBar() { clear(); }

drm::Progress ProgressBar::callback() {
    if (!enabled_) return drm::Progress();
    return [this](double fraction, const char* stage) {
        draw(fraction, stage);
        return true;
    };
}

void ProgressBar::draw(double fraction, const char* stage) {
    const int permille = int(std::min(1.0, std::max(0.0, fraction)) * 1000.0);
    if (permille == lastPermille_) return;
    lastPermille_ = permille;
    const int width = 30;
    const int filled = permille * width / 1000;
    std::fprintf(stderr, "\r\033[K%s [%s%s] %3d%% %s", label_.c_str(), std::string(size_t(filled), '#').c_str(),
                 std::string(size_t(width - filled), '.').c_str(), permille / 10, stage ? stage : "");
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::clear() {
    if (!drawn_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
    lastPermille_ = -1;
}

std::string fixed(double value, int decimals) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(decimals) << value;
    return out.str();
}

std::string fileName(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string fileStem(const std::string& path) {
    const std::string name = fileName(path);
    const size_t dot = name.find_last_of('.');
    return (dot == std::string::npos || dot == 0) ? name : name.substr(0, dot);
}

bool hasExtension(const std::string& path, const std::string& extension) {
    if (path.size() < extension.size()) return false;
    return std::equal(extension.begin(), extension.end(), path.end() - long(extension.size()),
                      [](char a, char b) { return std::tolower((unsigned char)a) == std::tolower((unsigned char)b); });
}

// The encoder's second thread would otherwise get an arena of its own,
// outside the huge-page advice (about three times the page faults on igea,
// and its vertex coder would run slower there than on one thread).
void shareOneMallocArena() {
#ifdef __GLIBC__
    mallopt(M_ARENA_MAX, 1);
#endif
}

// The tool's own bound (cli.h), measured on igea subdivided once and twice
// (docs/tuning.md); not one of the codec's limits.
constexpr size_t kLargeMeshVertices = size_t(1) << 18;

void mapLargeBlocksApart(size_t vertexCount) {
#ifdef __GLIBC__
    if (vertexCount > kLargeMeshVertices) mallopt(M_MMAP_THRESHOLD, 1 << 20);
#else
    (void)vertexCount;
#endif
}

}  // namespace cli
}  // namespace drm
