// takeCensus: see file_census.h. Deliberately written apart from the
// readers: its own tokenizing, its own header parse, its own body walk.
#include "file_census.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace drm {
namespace cli {

namespace {

std::string lowerExtension(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
    std::string extension = path.substr(dot + 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

// The lines of text, split at LF, CRLF or CR.
std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i) {
        if (i == text.size() || text[i] == '\n' || text[i] == '\r') {
            lines.push_back(text.substr(start, i - start));
            if (i + 1 < text.size() && text[i] == '\r' && text[i + 1] == '\n') ++i;
            start = i + 1;
        }
    }
    return lines;
}

std::vector<std::string> wordsOf(const std::string& line) {
    std::vector<std::string> words;
    size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at]))) ++at;
        const size_t start = at;
        while (at < line.size() && !std::isspace(static_cast<unsigned char>(line[at]))) ++at;
        if (at > start) words.push_back(line.substr(start, at - start));
    }
    return words;
}

bool wholeNumber(const std::string& word, uint64_t& value) {
    if (word.empty() || word.size() > 18 || !std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return false;
    value = std::strtoull(word.c_str(), nullptr, 10);
    return true;
}

void exactly(FileCensus& census, uint64_t triangles) {
    census.minTriangles = census.maxTriangles = triangles;
    census.known = true;
}

FileCensus objCensus(const std::string& text) {
    FileCensus census;
    uint64_t vertices = 0, triangles = 0;
    std::string statement;
    const auto count = [&]() {
        const std::vector<std::string> words = wordsOf(statement);
        statement.clear();
        if (words.empty()) return;
        if (words[0] == "v") ++vertices;
        if (words[0] == "f" && words.size() >= 4) triangles += words.size() - 3;
    };
    const bool byteOrderMark = text.compare(0, 3, "\xEF\xBB\xBF") == 0;
    for (std::string line : linesOf(byteOrderMark ? text.substr(3) : text)) {
        // A comment runs from a '#' that starts a word to the line's end.
        for (size_t i = 0; i < line.size(); ++i)
            if (line[i] == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(line[i - 1])))) {
                line.resize(i);
                break;
            }
        while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
        statement += line;
        if (!statement.empty() && statement.back() == '\\') {
            statement.back() = ' ';
            continue;
        }
        count();
    }
    count();
    census.vertices = vertices;
    census.vertexCountKnown = true;
    exactly(census, triangles);
    return census;
}

FileCensus offCensus(const std::string& text) {
    FileCensus census;
    // Lines of words, comments left out. The counts and the vertices'
    // coordinates (three words each) may break across lines anywhere; each
    // face is a line of its own: its corner count, its corners, maybe a
    // colour. Other keywords (COFF, NOFF, 4OFF, ...) put more words on a
    // vertex: those files are left uncounted.
    std::vector<std::vector<std::string>> lines;
    for (const std::string& line : linesOf(text)) {
        std::vector<std::string> words = wordsOf(line.substr(0, line.find('#')));
        if (!words.empty()) lines.push_back(words);
    }
    std::vector<std::string> words;  // the header's and vertices' words, as consumed
    size_t line = 0, word = 0;
    const auto next = [&](std::string& out) {
        if (line < lines.size() && word == lines[line].size()) ++line, word = 0;
        if (line >= lines.size()) return false;
        out = lines[line][word++];
        return true;
    };
    std::string first;
    if (!next(first)) return census;
    const bool named = first.size() >= 3 && first.compare(first.size() - 3, 3, "OFF") == 0;
    if (named && first != "OFF") return census;
    std::string counts[3];
    if (named) {
        if (!next(counts[0])) return census;
    } else {
        counts[0] = first;
    }
    uint64_t vertices = 0, faces = 0;
    if (!next(counts[1]) || !next(counts[2]) || !wholeNumber(counts[0], vertices) || !wholeNumber(counts[1], faces))
        return census;
    std::string coordinate;
    for (uint64_t i = 0; i < 3 * vertices; ++i)
        if (!next(coordinate)) return census;
    if (line < lines.size() && word != lines[line].size() && word != 0) return census;  // a face on a vertex's line
    if (line < lines.size() && word == lines[line].size()) ++line;
    if (lines.size() - line < faces) return census;
    uint64_t triangles = 0;
    for (uint64_t f = 0; f < faces; ++f) {
        uint64_t corners = 0;
        if (!wholeNumber(lines[line + f][0], corners) || corners < 3) return census;
        triangles += corners - 2;
    }
    census.vertices = vertices;
    census.vertexCountKnown = true;
    exactly(census, triangles);
    return census;
}

FileCensus stlCensus(const std::vector<uint8_t>& bytes) {
    FileCensus census;
    if (bytes.size() >= 84) {
        const uint64_t facets = uint64_t(bytes[80]) | uint64_t(bytes[81]) << 8 | uint64_t(bytes[82]) << 16 | uint64_t(bytes[83]) << 24;
        if (84 + 50 * facets == bytes.size()) {
            exactly(census, facets);
            return census;
        }
    }
    uint64_t facets = 0;
    for (const std::string& line : linesOf(std::string(bytes.begin(), bytes.end()))) {
        const std::vector<std::string> words = wordsOf(line);
        if (words.empty()) continue;
        std::string first = words[0];
        std::transform(first.begin(), first.end(), first.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (first == "endfacet") ++facets;
    }
    exactly(census, facets);
    return census;
}

// PLY: the header, then a walk over every element of the body that reads
// only list counts.
struct PlyProperty {
    int size = 0;       // of the scalar, or of a list's entries
    int countSize = 0;  // of a list's count; 0 for a scalar
    bool corners = false;
};
struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

int plyTypeSize(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32") return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

FileCensus plyCensus(const std::vector<uint8_t>& bytes) {
    FileCensus census;
    // The header is text up to the line "end_header".
    size_t at = 0;
    std::string format;
    std::vector<PlyElement> elements;
    bool ended = false;
    // Every header line ends as the first one does (LF, CRLF or CR), so a
    // binary body right after a CR-ended header keeps its first byte.
    size_t firstEnd = 0;
    while (firstEnd < bytes.size() && bytes[firstEnd] != '\n' && bytes[firstEnd] != '\r') ++firstEnd;
    const bool crlf = firstEnd + 1 < bytes.size() && bytes[firstEnd] == '\r' && bytes[firstEnd + 1] == '\n';
    const uint8_t ending = firstEnd < bytes.size() ? bytes[firstEnd] : uint8_t('\n');
    while (at < bytes.size() && !ended) {
        size_t end = at;
        while (end < bytes.size() && bytes[end] != ending) ++end;
        const std::vector<std::string> words = wordsOf(std::string(bytes.begin() + long(at), bytes.begin() + long(end)));
        if (crlf && end + 1 < bytes.size()) ++end;
        at = end + 1;
        if (words.empty()) continue;
        if (words[0] == "format" && words.size() >= 2) format = words[1];
        if (words[0] == "end_header") ended = true;
        if (words[0] == "element" && words.size() == 3) {
            PlyElement element;
            element.name = words[1];
            if (!wholeNumber(words[2], element.count)) return census;
            elements.push_back(element);
        }
        if (words[0] == "property" && !elements.empty()) {
            PlyProperty property;
            if (words.size() == 5 && words[1] == "list") {
                property.countSize = plyTypeSize(words[2]);
                property.size = plyTypeSize(words[3]);
                // The corners: vertex_indices, else vertex_index (one list a face).
                PlyElement& element = elements.back();
                const bool cornerName = words[4] == "vertex_indices" || words[4] == "vertex_index";
                property.corners = element.name == "face" && cornerName;
                for (PlyProperty& other : element.properties)
                    if (property.corners && other.corners) {
                        if (words[4] == "vertex_indices") other.corners = false;
                        else property.corners = false;
                    }
            } else if (words.size() == 3) {
                property.size = plyTypeSize(words[1]);
            }
            if (property.size == 0) return census;
            elements.back().properties.push_back(property);
        }
    }
    if (!ended) return census;
    const bool ascii = format == "ascii", big = format == "binary_big_endian";
    if (!ascii && !big && format != "binary_little_endian") return census;

    uint64_t triangles = 0;
    std::vector<std::string> tokens;
    size_t token = 0;
    if (ascii) tokens = wordsOf(std::string(bytes.begin() + long(std::min(at, bytes.size())), bytes.end()));
    // Reads a list count; false at the end of the data.
    const auto count = [&](int size, uint64_t& value) {
        if (ascii) return token < tokens.size() && wholeNumber(tokens[token++], value);
        if (bytes.size() - at < size_t(size)) return false;
        value = 0;
        for (int i = 0; i < size; ++i) value |= uint64_t(bytes[at + size_t(big ? i : size - 1 - i)]) << (8 * (size - 1 - i));
        at += size_t(size);
        return true;
    };
    const auto skip = [&](uint64_t values, int size) {
        if (ascii) {
            if (tokens.size() - token < values) return false;
            token += size_t(values);
            return true;
        }
        if ((bytes.size() - at) / size_t(size) < values) return false;
        at += size_t(values) * size_t(size);
        return true;
    };
    for (const PlyElement& element : elements) {
        if (element.name == "vertex") {
            census.vertices = element.count;
            census.vertexCountKnown = true;
        }
        if (element.properties.empty()) continue;  // items of nothing: no bytes to walk
        for (uint64_t item = 0; item < element.count; ++item)
            for (const PlyProperty& property : element.properties) {
                uint64_t entries = 1;
                if (property.countSize > 0 && !count(property.countSize, entries)) return census;
                if (!skip(entries, property.size)) return census;
                if (property.corners) {
                    triangles += entries >= 3 ? entries - 2 : 0;
                }
            }
    }
    exactly(census, triangles);
    // Triangle strips and range grids make triangles this scan does not
    // count: any number from the faces' up is possible.
    for (const PlyElement& element : elements)
        if ((element.name == "tristrips" || element.name == "range_grid") && element.count > 0)
            census.maxTriangles = UINT64_MAX;
    return census;
}

}  // namespace

FileCensus takeCensus(const std::string& path, const std::vector<uint8_t>& bytes) {
    const std::string extension = lowerExtension(path);
    if (extension == "ply") return plyCensus(bytes);
    if (extension == "obj") return objCensus(std::string(bytes.begin(), bytes.end()));
    if (extension == "off") return offCensus(std::string(bytes.begin(), bytes.end()));
    if (extension == "stl") return stlCensus(bytes);
    return FileCensus();
}

std::string censusMismatch(const FileCensus& census, uint64_t vertices, uint64_t triangles) {
    if (!census.known) return "";
    if (census.vertexCountKnown && vertices != census.vertices)
        return "the reader gave " + std::to_string(vertices) + " vertices where the file lists " + std::to_string(census.vertices);
    if (triangles < census.minTriangles || triangles > census.maxTriangles)
        return "the reader gave " + std::to_string(triangles) + " triangles where the file describes " +
               std::to_string(census.minTriangles);
    return "";
}

}  // namespace cli
}  // namespace drm
