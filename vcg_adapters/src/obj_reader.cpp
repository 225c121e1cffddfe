// readObj: see obj_reader.h for why drm does not use vcglib's OBJ reader.
#include "obj_reader.h"

#include <cerrno>
#include <cstdlib>
#include <limits>

namespace drm {
namespace vcgio {

namespace {

std::vector<std::string> splitBlanks(const std::string& line) {
    std::vector<std::string> tokens;
    size_t from = 0;
    while (from < line.size()) {
        while (from < line.size() && (line[from] == ' ' || line[from] == '\t' || line[from] == '\r')) ++from;
        size_t to = from;
        while (to < line.size() && line[to] != ' ' && line[to] != '\t' && line[to] != '\r') ++to;
        if (to > from) tokens.push_back(line.substr(from, to - from));
        from = to;
    }
    return tokens;
}

float parseCoordinate(const std::string& token, const std::string& where) {
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0') throw Error(where + ": '" + token + "' is not a number");
    return float(value);
}

}  // namespace

ObjContents readObj(const std::string& text) {
    ObjContents contents;
    drm::Mesh& mesh = contents.mesh;
    // Positive indices are checked once all vertices are known (some writers
    // put faces before the vertices they use); negative ones are relative to
    // the vertices read so far, as the format says.
    struct PendingCheck { long index; size_t line; };
    std::vector<PendingCheck> positiveIndices;

    size_t position = 0, lineNumber = 0;
    auto nextLine = [&]() {
        size_t end = text.find('\n', position);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(position, end - position);
        position = end + 1;
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        return line;
    };
    while (position < text.size()) {
        std::string line = nextLine();
        // A trailing backslash continues the statement on the next line.
        while (!line.empty() && line.back() == '\\') {
            line.back() = ' ';
            if (position < text.size()) line += nextLine();
        }
        const std::vector<std::string> tokens = splitBlanks(line);
        if (tokens.empty() || tokens[0][0] == '#') continue;
        const std::string where = "line " + std::to_string(lineNumber);
        const std::string& keyword = tokens[0];

        if (keyword == "v") {
            if (tokens.size() < 4) throw Error(where + ": a vertex needs three coordinates");
            for (int k = 1; k <= 3; ++k) mesh.positions.push_back(parseCoordinate(tokens[size_t(k)], where));
            if (tokens.size() >= 7) contents.vertexColours = true;
        } else if (keyword == "vt") {
            contents.textureCoordinates = true;
        } else if (keyword == "vn") {
            contents.normals = true;
        } else if (keyword == "usemtl" || keyword == "mtllib") {
            contents.materials = true;
        } else if (keyword == "l" || keyword == "p") {
            contents.linesOrPoints = true;
        } else if (keyword == "f") {
            const size_t cornerCount = tokens.size() - 1;
            if (cornerCount < 3) throw Error(where + ": a face needs at least three corners");
            std::vector<uint32_t> corners;
            for (size_t c = 1; c < tokens.size(); ++c) {
                const std::string vertexPart = tokens[c].substr(0, tokens[c].find('/'));
                errno = 0;
                char* endOfNumber = nullptr;
                const long index = std::strtol(vertexPart.c_str(), &endOfNumber, 10);
                if (endOfNumber == vertexPart.c_str() || *endOfNumber != '\0' || errno != 0 || index == 0)
                    throw Error(where + ": '" + tokens[c] + "' is not a vertex reference");
                const long known = long(mesh.vertexCount());
                long resolved;
                if (index < 0) {
                    if (-index > known)
                        throw Error(where + ": vertex reference " + vertexPart + " goes before the first vertex");
                    resolved = known + index;
                } else {
                    if (index - 1 > long(std::numeric_limits<uint32_t>::max() - 1))
                        throw Error(where + ": vertex reference " + vertexPart + " is too large");
                    resolved = index - 1;
                }
                corners.push_back(uint32_t(resolved));
                if (index > 0) positiveIndices.push_back(PendingCheck{index, lineNumber});
            }
            // Fan split in place: (0, i, i + 1) keeps the polygon's orientation.
            for (size_t i = 1; i + 1 < corners.size(); ++i) {
                mesh.triangles.push_back(corners[0]);
                mesh.triangles.push_back(corners[i]);
                mesh.triangles.push_back(corners[i + 1]);
            }
            if (cornerCount > 3) {
                ++contents.polygons;
                contents.trianglesFromPolygons += cornerCount - 2;
            }
        }
        // Other statements (g, o, s, ...) carry nothing a .drm file keeps.
    }
    for (const PendingCheck& check : positiveIndices) {
        if (size_t(check.index) > mesh.vertexCount())
            throw Error("line " + std::to_string(check.line) + ": face refers to vertex " +
                        std::to_string(check.index) + ", but the file has " +
                        std::to_string(mesh.vertexCount()) + " vertices");
    }
    return contents;
}

}  // namespace vcgio
}  // namespace drm
