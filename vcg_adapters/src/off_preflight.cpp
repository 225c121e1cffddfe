// preflightOff: see format_preflight.h for why. The reading order below
// follows vcglib's ImporterOFF::OpenStream step by step, so that a file
// accepted here is read by vcglib without surprises.
#include "format_preflight.h"

#include <drmcodec/drmcodec.h>

#include <cerrno>
#include <cstdlib>

namespace drm {
namespace vcgio {

namespace {

// Lines as vcglib's ImporterOFF::TokenizeNextLine sees them: lines that are
// empty or start with '#' or '\r' are skipped; the rest are split on blanks.
// A line of blanks gives no tokens (vcglib then fails or reads out of
// bounds, so callers treat it as an error).
class OffLines {
public:
    explicit OffLines(const std::string& text) : text_(text) {}

    // False at the end of the text.
    bool next(std::vector<std::string>& tokens) {
        tokens.clear();
        while (position_ < text_.size()) {
            size_t end = text_.find('\n', position_);
            if (end == std::string::npos) end = text_.size();
            const std::string line = text_.substr(position_, end - position_);
            position_ = end + 1;
            ++lineNumber_;
            if (line.empty() || line[0] == '#' || line[0] == '\r') continue;
            size_t from = 0;
            while (from < line.size()) {
                while (from < line.size() && isBlank(line[from])) ++from;
                size_t to = from;
                while (to < line.size() && !isBlank(line[to])) ++to;
                if (to > from) tokens.push_back(line.substr(from, to - from));
                from = to;
            }
            return true;
        }
        return false;
    }

    std::string where() const { return "line " + std::to_string(lineNumber_); }

private:
    static bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

    const std::string& text_;
    size_t position_ = 0;
    size_t lineNumber_ = 0;
};

long parseInteger(const std::string& token, const std::string& where) {
    errno = 0;
    char* end = nullptr;
    const long value = std::strtol(token.c_str(), &end, 10);
    if (end == token.c_str() || *end != '\0' || errno != 0)
        throw Error(ErrorKind::InvalidInput, where + ": '" + token + "' is not an integer");
    return value;
}

void parseNumber(const std::string& token, const std::string& where) {
    char* end = nullptr;
    std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0') throw Error(ErrorKind::InvalidInput, where + ": '" + token + "' is not a number");
}

}  // namespace

uint64_t preflightOff(const std::string& text) {
    OffLines lines(text);
    std::vector<std::string> tokens;
    if (!lines.next(tokens) || tokens.empty() || tokens[0].rfind("OFF") == std::string::npos)
        throw Error(ErrorKind::InvalidInput, "not an OFF file: its first line has no OFF keyword");

    // The keyword's prefix letters say what each vertex carries.
    const std::string& keyword = tokens[0];
    bool normals = false, colours = false, textureCoordinates = false;
    for (int u = int(keyword.rfind("OFF")) - 1; u >= 0; --u) {
        const char c = keyword[size_t(u)];
        if (c == 'C') colours = true;
        else if (c == 'N') normals = true;
        else if (c == 'T' && u > 0 && keyword[size_t(u) - 1] == 'S') textureCoordinates = true;
        else if (c == '4' || c == 'n') throw Error(ErrorKind::InvalidInput, "'" + keyword + "' files (homogeneous or n-dimensional) are not supported");
    }

    if (tokens.size() == 1) lines.next(tokens);
    else tokens.erase(tokens.begin());
    if (tokens.size() < 3) throw Error(ErrorKind::InvalidInput, lines.where() + ": expected the vertex, face and edge counts");
    const long vertexCount = parseInteger(tokens[0], lines.where());
    const long faceCount = parseInteger(tokens[1], lines.where());
    // Each vertex needs at least 6 bytes ("0 0 0\n"), each face 8 ("3 0 1 2\n"):
    // larger counts cannot fit and would only make the reader allocate wildly.
    if (vertexCount < 0 || size_t(vertexCount) > text.size() / 6)
        throw Error(ErrorKind::InvalidInput, "the header's vertex count " + tokens[0] + " does not fit in the file");
    if (faceCount < 0 || size_t(faceCount) > text.size() / 8)
        throw Error(ErrorKind::InvalidInput, "the header's face count " + tokens[1] + " does not fit in the file");

    // Vertices: coordinates (and normals, texture coordinates) are read token
    // by token across line breaks; colours are whatever else is on the line.
    lines.next(tokens);
    size_t k = 0;
    long vertex = 0;
    auto nextToken = [&]() -> const std::string& {
        if (k == tokens.size()) {
            if (!lines.next(tokens) || tokens.empty())
                throw Error(ErrorKind::InvalidInput, "the file ends inside vertex " + std::to_string(vertex) + " of " +
                            std::to_string(vertexCount));
            k = 0;
        }
        return tokens[k++];
    };
    for (; vertex < vertexCount; ++vertex) {
        for (int j = 0; j < (normals ? 6 : 3); ++j) parseNumber(nextToken(), lines.where());
        if (colours) {
            const long components = long(tokens.size()) - long(k) - (textureCoordinates ? 2 : 0);
            if (components < 0 || components > 4)
                throw Error(ErrorKind::InvalidInput, lines.where() + ": vertex " + std::to_string(vertex) + " has " +
                            std::to_string(components) + " colour components");
            k += size_t(components);
        }
        if (textureCoordinates)
            for (int j = 0; j < 2; ++j) nextToken();
    }

    // Faces: each starts on a new line with its corner count.
    uint64_t triangles = 0;
    for (long face = 0; face < faceCount; ++face) {
        if (!lines.next(tokens))
            throw Error(ErrorKind::InvalidInput, "the file ends after " + std::to_string(face) + " of the header's " +
                        std::to_string(faceCount) + " faces");
        if (tokens.empty()) throw Error(ErrorKind::InvalidInput, lines.where() + ": blank line where face " + std::to_string(face) + " should be");
        const long corners = parseInteger(tokens[0], lines.where());
        if (corners < 3 || size_t(corners) > text.size() / 2)
            throw Error(ErrorKind::InvalidInput, lines.where() + ": face " + std::to_string(face) + " has " + tokens[0] + " corners");
        triangles += uint64_t(corners - 2);
        k = 1;
        for (long j = 0; j < corners; ++j) {
            if (k == tokens.size()) {
                if (!lines.next(tokens) || tokens.empty())
                    throw Error(ErrorKind::InvalidInput, "the file ends inside face " + std::to_string(face));
                k = 0;
            }
            const long index = parseInteger(tokens[k++], lines.where());
            if (index < 0 || index >= vertexCount)
                throw Error(ErrorKind::InvalidInput, lines.where() + ": face " + std::to_string(face) + " refers to vertex " +
                            std::to_string(index) + ", but the file has " + std::to_string(vertexCount) +
                            " vertices");
        }
    }
    return triangles;
}

}  // namespace vcgio
}  // namespace drm
