// readObj: see obj_reader.h for why drm does not use vcglib's OBJ reader.
#include "obj_reader.h"

#include "text_lines.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <limits>

namespace drm {
namespace vcgio {

namespace {

float parseCoordinate(const std::string& token, const std::string& where) {
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0') throw Error(ErrorKind::InvalidInput, where + ": '" + token + "' is not a number");
    return float(value);
}

}  // namespace

namespace {

// One of a corner's references (`v`, `vt` or `vn`), resolved to 0-based.
// Positive references are checked once the whole file is read (some
// writers put faces before the data they use); negative ones are relative
// to what was read so far, as the format says.
struct Reference {
    long index = -1;  // 0-based, -1: none
};

long resolveReference(const std::string& part, size_t known, const std::string& where, const char* what,
                      const std::string& token) {
    errno = 0;
    char* endOfNumber = nullptr;
    const long index = std::strtol(part.c_str(), &endOfNumber, 10);
    if (endOfNumber == part.c_str() || *endOfNumber != '\0' || errno != 0 || index == 0)
        throw Error(ErrorKind::InvalidInput, where + ": '" + token + "' is not a " + what + " reference");
    if (index < 0) {
        if (-index > long(known)) throw Error(ErrorKind::InvalidInput, where + ": " + what + " reference " + part + " goes before the first one");
        return long(known) + index;
    }
    if (index - 1 > long(std::numeric_limits<uint32_t>::max() - 1))
        throw Error(ErrorKind::InvalidInput, where + ": " + what + " reference " + part + " is too large");
    return index - 1;
}

uint8_t colourByte(float value, float scale) {
    const float scaled = value * scale;
    if (!(scaled > 0)) return 0;
    if (scaled >= 255) return 255;
    return uint8_t(std::lround(scaled));
}

}  // namespace

ObjContents readObj(const std::string& text) {
    // A byte order mark: UTF-8's is skipped; UTF-16 text is not OBJ as
    // drm reads it (every other byte would be a NUL).
    if (text.compare(0, 2, "\xFE\xFF") == 0 || text.compare(0, 2, "\xFF\xFE") == 0)
        throw Error(ErrorKind::InvalidInput, "the file is UTF-16 text: save it as UTF-8 or ASCII");
    ObjContents contents;
    drm::Mesh& mesh = contents.mesh;
    struct PendingCheck { long index; size_t line; const char* what; };
    std::vector<PendingCheck> positiveIndices;
    std::vector<float> texCoords, normals, colours;  // as read: 2, 3, 3 per item
    std::vector<bool> hasColour;
    std::vector<long> cornerTexCoord, cornerNormal;  // per triangle corner, -1: none
    std::vector<uint32_t> faceMaterial;
    uint32_t currentMaterial = 0;
    bool anyMaterial = false;
    auto materialIndex = [&mesh](const std::string& name) {
        for (size_t i = 0; i < mesh.materials.size(); ++i)
            if (mesh.materials[i] == name) return uint32_t(i);
        mesh.materials.push_back(name);
        return uint32_t(mesh.materials.size() - 1);
    };

    size_t position = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0, lineNumber = 0;
    auto nextLine = [&]() {
        std::string line = takeLine(text, position);
        ++lineNumber;
        stripComment(line);
        return line;
    };
    while (position < text.size()) {
        std::string line = nextLine();
        // A trailing backslash continues the statement on the next line.
        while (!line.empty() && line.back() == '\\') {
            line.back() = ' ';
            if (position < text.size()) line += nextLine();
        }
        const std::vector<std::string> tokens = splitWords(line);
        if (tokens.empty()) continue;
        const std::string where = "line " + std::to_string(lineNumber);
        const std::string& keyword = tokens[0];

        if (keyword == "v") {
            if (tokens.size() < 4) throw Error(ErrorKind::InvalidInput, where + ": a vertex needs three coordinates");
            for (int k = 1; k <= 3; ++k) mesh.positions.push_back(parseCoordinate(tokens[size_t(k)], where));
            const bool coloured = tokens.size() >= 7;
            hasColour.push_back(coloured);
            for (int k = 4; k <= 6; ++k) {
                colours.push_back(coloured ? parseCoordinate(tokens[size_t(k)], where) : 1.0f);
                if (!std::isfinite(colours.back()))
                    throw Error(ErrorKind::InvalidInput, where + ": the colour of vertex " + std::to_string(hasColour.size()) + " is not finite");
            }
        } else if (keyword == "vt") {
            if (tokens.size() < 2) throw Error(ErrorKind::InvalidInput, where + ": a texture coordinate needs at least u");
            texCoords.push_back(parseCoordinate(tokens[1], where));
            texCoords.push_back(tokens.size() >= 3 ? parseCoordinate(tokens[2], where) : 0.0f);
            if (tokens.size() >= 4 && parseCoordinate(tokens[3], where) != 0.0f) contents.texCoordW = true;
            if (!std::isfinite(texCoords[texCoords.size() - 2]) || !std::isfinite(texCoords.back()))
                throw Error(ErrorKind::InvalidInput, where + ": texture coordinate " + std::to_string(texCoords.size() / 2) + " is not finite");
        } else if (keyword == "vn") {
            if (tokens.size() < 4) throw Error(ErrorKind::InvalidInput, where + ": a normal needs three coordinates");
            for (int k = 1; k <= 3; ++k) normals.push_back(parseCoordinate(tokens[size_t(k)], where));
            for (int k = 1; k <= 3; ++k)
                if (!std::isfinite(normals[normals.size() - size_t(k)]))
                    throw Error(ErrorKind::InvalidInput, where + ": normal " + std::to_string(normals.size() / 3) + " is not finite");
        } else if (keyword == "usemtl") {
            // A material name may hold blanks: everything after the keyword.
            const size_t from = line.find_first_not_of(" \t", line.find("usemtl") + 6);
            const std::string name = from == std::string::npos ? "" : line.substr(from);
            if (!anyMaterial && !faceMaterial.empty()) materialIndex("");  // faces before the first usemtl
            anyMaterial = true;
            currentMaterial = materialIndex(name);
        } else if (keyword == "mtllib") {
            const size_t from = line.find_first_not_of(" \t", line.find("mtllib") + 6);
            const std::string name = from == std::string::npos ? "" : line.substr(from);
            if (contents.mtllib.empty()) contents.mtllib = name;
            else if (name != contents.mtllib) ++contents.otherLibraries;
        } else if (keyword == "l" || keyword == "p") {
            contents.linesOrPoints = true;
        } else if (keyword == "f") {
            const size_t cornerCount = tokens.size() - 1;
            if (cornerCount < 3) throw Error(ErrorKind::InvalidInput, where + ": a face needs at least three corners");
            std::vector<uint32_t> corners;
            std::vector<long> tex, nor;
            for (size_t c = 1; c < tokens.size(); ++c) {
                const std::string& token = tokens[c];
                const size_t slash1 = token.find('/');
                const std::string vertexPart = token.substr(0, slash1);
                std::string texPart, normalPart;
                if (slash1 != std::string::npos) {
                    const size_t slash2 = token.find('/', slash1 + 1);
                    texPart = token.substr(slash1 + 1, slash2 == std::string::npos ? std::string::npos : slash2 - slash1 - 1);
                    if (slash2 != std::string::npos) normalPart = token.substr(slash2 + 1);
                }
                const long v = resolveReference(vertexPart, mesh.vertexCount(), where, "vertex", token);
                corners.push_back(uint32_t(v));
                if (vertexPart[0] != '-') positiveIndices.push_back(PendingCheck{v + 1, lineNumber, "vertex"});
                long t = -1, n = -1;
                if (!texPart.empty()) {
                    t = resolveReference(texPart, texCoords.size() / 2, where, "texture coordinate", token);
                    if (texPart[0] != '-') positiveIndices.push_back(PendingCheck{t + 1, lineNumber, "texture coordinate"});
                }
                if (!normalPart.empty()) {
                    n = resolveReference(normalPart, normals.size() / 3, where, "normal", token);
                    if (normalPart[0] != '-') positiveIndices.push_back(PendingCheck{n + 1, lineNumber, "normal"});
                }
                tex.push_back(t);
                nor.push_back(n);
            }
            // Fan split in place: (0, i, i + 1) keeps the polygon's orientation.
            for (size_t i = 1; i + 1 < corners.size(); ++i) {
                for (size_t c : {size_t(0), i, i + 1}) {
                    mesh.triangles.push_back(corners[c]);
                    cornerTexCoord.push_back(tex[c]);
                    cornerNormal.push_back(nor[c]);
                }
                faceMaterial.push_back(currentMaterial);
            }
            if (cornerCount > 3) {
                ++contents.polygons;
                contents.trianglesFromPolygons += cornerCount - 2;
            }
        }
        // Other statements (g, o, s, ...) carry nothing a .drm file keeps.
    }
    const size_t counts[3] = {mesh.vertexCount(), texCoords.size() / 2, normals.size() / 3};
    for (const PendingCheck& check : positiveIndices) {
        const std::string what = check.what;
        const size_t known = what == "vertex" ? counts[0] : what == "normal" ? counts[2] : counts[1];
        if (size_t(check.index) > known)
            throw Error(ErrorKind::InvalidInput, "line " + std::to_string(check.line) + ": face refers to " + what + " " +
                        std::to_string(check.index) + ", but the file has " + std::to_string(known) + " of them");
    }

    // Vertex colours: 0..1 as the format's extension says; some writers
    // give 0..255.
    size_t coloured = 0;
    float largest = 0;
    for (size_t i = 0; i < hasColour.size(); ++i) {
        if (!hasColour[i]) continue;
        ++coloured;
        for (int k = 0; k < 3; ++k) largest = std::max(largest, colours[3 * i + size_t(k)]);
    }
    if (coloured > 0) {
        contents.coloursOver255 = largest > 1.0f;
        const float scale = contents.coloursOver255 ? 1.0f : 255.0f;
        contents.verticesWithoutColour = hasColour.size() - coloured;
        mesh.colors.resize(4 * hasColour.size());
        for (size_t i = 0; i < hasColour.size(); ++i) {
            for (int k = 0; k < 3; ++k)
                mesh.colors[4 * i + size_t(k)] = hasColour[i] ? colourByte(colours[3 * i + size_t(k)], scale) : 255;
            mesh.colors[4 * i + 3] = 255;
        }
    }

    const size_t cornerCount = mesh.triangles.size();
    size_t withTex = 0, withNormal = 0;
    for (size_t c = 0; c < cornerCount; ++c) {
        if (cornerTexCoord[c] >= 0) ++withTex;
        if (cornerNormal[c] >= 0) ++withNormal;
    }
    contents.unusedTexCoords = withTex == 0 && !texCoords.empty();
    contents.unusedNormals = withNormal == 0 && !normals.empty();
    if (withTex > 0) {
        contents.cornersWithoutTexCoord = cornerCount - withTex;
        mesh.cornerTexCoords.assign(2 * cornerCount, 0.0f);
        for (size_t c = 0; c < cornerCount; ++c)
            if (cornerTexCoord[c] >= 0)
                for (int k = 0; k < 2; ++k)
                    mesh.cornerTexCoords[2 * c + size_t(k)] = texCoords[2 * size_t(cornerTexCoord[c]) + size_t(k)];
    }
    if (withNormal > 0) {
        contents.cornersWithoutNormal = cornerCount - withNormal;
        std::vector<float> corner(3 * cornerCount, 0.0f);
        for (size_t c = 0; c < cornerCount; ++c)
            if (cornerNormal[c] >= 0)
                for (int k = 0; k < 3; ++k) corner[3 * c + size_t(k)] = normals[3 * size_t(cornerNormal[c]) + size_t(k)];
        // Per vertex if every corner of each vertex has the same normal
        // (the usual `f a//a` layout); vertices no face uses get 0, 0, 0.
        std::vector<float> perVertex(3 * mesh.vertexCount(), 0.0f);
        std::vector<bool> assigned(mesh.vertexCount(), false);
        bool consistent = contents.cornersWithoutNormal == 0;
        for (size_t c = 0; c < cornerCount && consistent; ++c) {
            const uint32_t v = mesh.triangles[c];
            if (!assigned[v]) {
                assigned[v] = true;
                for (int k = 0; k < 3; ++k) perVertex[3 * size_t(v) + size_t(k)] = corner[3 * c + size_t(k)];
            } else {
                for (int k = 0; k < 3; ++k)
                    if (std::memcmp(&perVertex[3 * size_t(v) + size_t(k)], &corner[3 * c + size_t(k)], sizeof(float)) != 0)
                        consistent = false;
            }
        }
        if (consistent) mesh.normals = std::move(perVertex);
        else mesh.cornerNormals = std::move(corner);
    }
    if (anyMaterial) mesh.faceMaterial = std::move(faceMaterial);
    return contents;
}

}  // namespace vcgio
}  // namespace drm
