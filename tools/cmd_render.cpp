// drm render IN OUT.png: a picture of a mesh or .drm file, optionally with
// faces coloured by their distance rank (the paper's Figure 1), drawn in
// software so it needs no GPU and no display.
#include "cli.h"
#include "commands.h"
#include "mesh_input.h"
#include "ranked_mesh.h"
#include "render/module.h"
#include "render/picture.h"

#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>
#include <drm_vcg/rank_palette.h>

#include <cstdio>
#include <cstdlib>

namespace drm {
namespace cli {

const char* const kRenderHelp =
    "usage: drm render IN OUT.png [--by-rank] [--view V] [--size WxH]\n"
    "                  [--bits N] [--predictor P] [--curvature on|off] [--geometry G] [--levers L]\n"
    "                  [--keep-vertex-order]\n"
    "\n"
    "Draws IN, flat-shaded in light grey under a headlight, into a PNG picture\n"
    "with its file name on top. Rendered in software: no GPU or display needed.\n"
    "\n"
    "options:\n"
    "  --by-rank    colour each face by the rank code that created it, as\n"
    "               'drm ranks' does, and add a legend (colour, share of\n"
    "               faces) and the connectivity bits per vertex. A mesh is\n"
    "               encoded with the encode options given (--bits to\n"
    "               --keep-vertex-order, as for 'drm encode'); a .drm file\n"
    "               shows its own ranks (options cannot be given).\n"
    "  --view V     front (looking down -Z, Y up; the default), back, left\n"
    "               (from -X), right (from +X), top (from +Y), bottom or iso\n"
    "               (from the +X+Y+Z corner)\n"
    "  --size WxH   picture size in pixels (default 800x600; 64 to 8192 each)\n"
    "\n"
    "Without --by-rank a mesh is drawn as read, so meshes the codec refuses can\n"
    "be looked at too; a .drm file is decoded, and the title gives its rate.\n";

namespace {

struct Size {
    int width = 800, height = 600;
};

Size parseSize(const std::string& text) {
    Size size;
    const size_t x = text.find('x');
    auto number = [](const std::string& digits, int& out) {
        if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos)
            return false;
        out = std::atoi(digits.c_str());
        return out >= render::kMinSide && out <= render::kMaxSide;
    };
    if (x == std::string::npos || !number(text.substr(0, x), size.width) || !number(text.substr(x + 1), size.height))
        throw UsageError("--size takes WIDTHxHEIGHT, each from " + std::to_string(render::kMinSide) + " to " +
                         std::to_string(render::kMaxSide) + " pixels (got '" + text + "')");
    return size;
}

render::View parseViewOption(const Arguments& parsed) {
    render::View view = render::View::Front;
    const std::string name = parsed.value("--view", "front");
    if (!render::parseView(name, view))
        throw UsageError("--view takes " + std::string(render::viewNames()) + " (got '" + name + "')");
    return view;
}

// The rank colours and the legend: one entry per bucket of rank_palette.h,
// so the picture reads like `drm ranks` output in MeshLab.
void colourByRank(const std::vector<uint32_t>& faceRank, render::Scene& scene) {
    std::vector<uint64_t> facesPerBucket(drm::vcgio::kRankBucketCount, 0);
    scene.faceColour.reserve(faceRank.size());
    for (uint32_t rank : faceRank) {
        const drm::vcgio::RankColour c = drm::vcgio::rankColour(rank);
        scene.faceColour.push_back({c.r, c.g, c.b});
        ++facesPerBucket[size_t(drm::vcgio::rankBucket(rank))];
    }
    for (int bucket = 0; bucket < drm::vcgio::kRankBucketCount; ++bucket) {
        const drm::vcgio::RankColour c = drm::vcgio::rankBucketColour(bucket);
        const double share = faceRank.empty() ? 0.0 : double(facesPerBucket[size_t(bucket)]) / double(faceRank.size());
        scene.legend.push_back({drm::vcgio::rankBucketName(bucket), {c.r, c.g, c.b}, share});
    }
}

}  // namespace

int runRender(const std::vector<std::string>& args) {
    std::vector<std::string> valued = encodeOptionNames();
    valued.insert(valued.end(), {"--view", "--size"});
    std::vector<std::string> flags = encodeFlagNames();
    flags.push_back("--by-rank");
    const Arguments parsed = parseArguments("render", args, valued, flags);
    parsed.expectPositional(2, 2, "an input mesh or .drm file and an output .png file");
    const std::string& input = parsed.positional[0];
    const std::string& output = parsed.positional[1];
    if (!hasExtension(output, ".png")) throw UsageError("the output of 'render' is a .png file (got '" + output + "')");
    const bool byRank = parsed.has("--by-rank");
    render::Scene scene;
    scene.view = parseViewOption(parsed);
    if (parsed.has("--size")) {
        const Size size = parseSize(parsed.value("--size"));
        scene.width = size.width;
        scene.height = size.height;
    }

    ProgressBar bar("render");
    RankedMesh ranked;
    bool rated = true;  // whether the codec ran, so the rate is known
    if (byRank) {
        ranked = loadRankedMesh(input, parsed, bar);
    } else {
        for (const std::string& option : encodeOptionNames())
            if (parsed.has(option)) throw UsageError(option + " only matters with --by-rank");
        for (const std::string& option : encodeFlagNames())
            if (parsed.has(option)) throw UsageError(option + " only matters with --by-rank");
        if (hasExtension(input, ".drm")) {
            ranked = decodeRankedMesh(input, bar);
        } else {
            drm::vcgio::LoadedMesh loaded = drm::vcgio::loadMesh(input);
            ranked.mesh = std::move(loaded.mesh);
            ranked.notes = std::move(loaded.notes);
            rated = false;
        }
    }
    bar.clear();

    scene.mesh = &ranked.mesh;
    if (byRank)
        colourByRank(ranked.faceRank, scene);
    else
        scene.faceColour.assign(ranked.mesh.faceCount(), render::Rgb{200, 200, 200});  // light grey
    // Most telling first: a narrow picture cuts the title's end.
    const std::string dot = "  \xc2\xb7  ";  // a middle dot, UTF-8
    scene.title = fileName(input);
    if (rated)
        scene.title += dot + "connectivity " + fixed(ranked.stats.connectivityBitsPerVertex(), 3) + " bits per vertex (" +
                       std::to_string(ranked.stats.bits) + "-bit grid)";
    scene.title += dot + std::to_string(ranked.mesh.vertexCount()) + " vertices, " +
                   std::to_string(ranked.mesh.faceCount()) + " faces";

    std::vector<uint8_t> png;
    try {
        png = render::renderPngInModule(scene);
    } catch (const drm::Error& e) {
        throw drm::Error(e.kind(), "cannot render " + input + ": " + e.what());
    }
    drm::vcgio::writeFileAtomically(output, png);

    printNotes(ranked.notes);
    std::printf("%s -> %s: %dx%d, %s view%s\n", input.c_str(), output.c_str(), scene.width, scene.height,
                parsed.value("--view", "front").c_str(), byRank ? ", faces coloured by rank" : "");
    for (const render::LegendEntry& entry : scene.legend)
        std::printf("  %-15s %7s%%\n", entry.label.c_str(), fixed(100.0 * entry.share, 2).c_str());
    return 0;
}

}  // namespace cli
}  // namespace drm
