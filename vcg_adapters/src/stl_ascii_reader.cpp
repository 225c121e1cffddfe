// readAsciiStl: see stl_ascii_reader.h.
#include "stl_ascii_reader.h"

#include "text_lines.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <vector>

namespace drm {
namespace vcgio {

namespace {

std::string lower(std::string word) {
    std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return word;
}

}  // namespace

AsciiStl readAsciiStl(const std::string& text) {
    AsciiStl stl;
    enum class Place { Outside, InSolid, InFacet, InLoop, LoopClosed } place = Place::Outside;
    std::vector<float> corners;  // of the facet being read
    size_t position = 0, lineNumber = 0;
    while (position < text.size()) {
        const std::vector<std::string> words = splitWords(takeLine(text, position));
        ++lineNumber;
        if (words.empty()) continue;
        const std::string where = "line " + std::to_string(lineNumber);
        const std::string keyword = lower(words[0]);
        const auto expect = [&](Place wanted, const char* what) {
            if (place != wanted) throw Error(ErrorKind::InvalidInput, where + ": '" + words[0] + "' " + what);
        };
        if (keyword == "solid") {
            expect(Place::Outside, "inside another solid (an endsolid is missing)");
            place = Place::InSolid;
            ++stl.solids;
        } else if (keyword == "endsolid") {
            expect(Place::InSolid, "inside a facet or outside any solid");
            place = Place::Outside;
        } else if (keyword == "facet") {
            expect(Place::InSolid, "outside a solid or inside another facet");
            place = Place::InFacet;
            corners.clear();
        } else if (keyword == "outer") {
            expect(Place::InFacet, "outside a facet");
            place = Place::InLoop;
        } else if (keyword == "vertex") {
            expect(Place::InLoop, "outside a facet's outer loop");
            if (words.size() != 4) throw Error(ErrorKind::InvalidInput, where + ": a vertex needs three coordinates");
            for (size_t k = 1; k <= 3; ++k) {
                char* end = nullptr;
                const double value = std::strtod(words[k].c_str(), &end);
                if (end == words[k].c_str() || *end != '\0')
                    throw Error(ErrorKind::InvalidInput, where + ": '" + words[k] + "' is not a number");
                corners.push_back(float(value));
            }
        } else if (keyword == "endloop") {
            expect(Place::InLoop, "outside a facet's outer loop");
            place = Place::LoopClosed;
        } else if (keyword == "endfacet") {
            expect(Place::LoopClosed, "before its facet's endloop");
            if (corners.size() != 9)
                throw Error(ErrorKind::InvalidInput, where + ": facet " + std::to_string(stl.soup.faceCount()) + " has " +
                            std::to_string(corners.size() / 3) + " vertices (STL facets are triangles)");
            const uint32_t first = uint32_t(stl.soup.vertexCount());
            stl.soup.positions.insert(stl.soup.positions.end(), corners.begin(), corners.end());
            for (uint32_t k = 0; k < 3; ++k) stl.soup.triangles.push_back(first + k);
            place = Place::InSolid;
        } else {
            throw Error(ErrorKind::InvalidInput, where + ": unknown statement '" + words[0] + "'");
        }
    }
    if (place != Place::Outside)
        throw Error(ErrorKind::InvalidInput, "the file ends inside " +
                    std::string(place == Place::InSolid ? "a solid (no endsolid)" : "facet " + std::to_string(stl.soup.faceCount())) +
                    " (truncated?)");
    return stl;
}

}  // namespace vcgio
}  // namespace drm
