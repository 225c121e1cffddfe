// parseHeader (see ply_header.h): the header's lines, from "ply" to
// end_header, into elements and typed properties. Each line is checked as it
// is read, and a refusal names the line. Only the comments that can mean
// something (TextureFile, num_cols, num_rows) are copied, since a header may
// hold megabytes of others.
#include "ply_header.h"

#include "drm_vcg/joined_list.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <set>

namespace drm {
namespace vcgio {
namespace ply {

bool scalarNamed(const std::string& text, Scalar& type) {
    for (size_t i = 0; i < sizeof kScalars / sizeof kScalars[0]; ++i)
        if (text == kScalars[i].name || text == kScalars[i].alias) {
            type = Scalar(i);
            return true;
        }
    return false;
}

std::string typeList(unsigned types) {
    std::vector<std::string> names;
    for (size_t i = 0; i < sizeof kScalars / sizeof kScalars[0]; ++i)
        if (types & (1u << i)) names.push_back(kScalars[i].name);
    return joinList(names);
}

namespace {

std::vector<std::string> splitBlanks(const uint8_t* from, const uint8_t* to) {
    std::vector<std::string> tokens;
    while (from < to) {
        while (from < to && isBlank(*from)) ++from;
        const uint8_t* end = from;
        while (end < to && !isBlank(*end)) ++end;
        if (end > from) tokens.emplace_back(reinterpret_cast<const char*>(from), size_t(end - from));
        from = end;
    }
    return tokens;
}

bool startsWithWord(const std::string& text, const char* word) {
    const size_t n = std::strlen(word);
    return text.compare(0, n, word) == 0 && (text.size() == n || text[n] == ' ' || text[n] == '\t');
}

// `comment` and `obj_info` text (after the keyword and its blanks): texture
// names, and the grid size of Stanford range scans.
void readCommentText(const std::string& text, Header& header) {
    if (startsWithWord(text, "TextureFile")) {
        // The rest of the line after one blank, byte for byte: names may hold
        // blanks, braces, tildes and any UTF-8.
        const size_t from = std::strlen("TextureFile") + 1;
        header.textures.push_back(text.size() > from ? text.substr(from) : std::string());
    } else if (startsWithWord(text, "num_cols") || startsWithWord(text, "num_rows")) {
        const long long value = std::strtoll(text.c_str() + 8, nullptr, 10);
        (text[4] == 'c' ? header.gridColumns : header.gridRows) = value;
    }
}

Kind kindOf(const std::string& name) {
    if (name == "vertex") return Kind::Vertex;
    if (name == "face") return Kind::Face;
    if (name == "tristrips") return Kind::Tristrips;
    if (name == "range_grid") return Kind::RangeGrid;
    return Kind::Other;
}

}  // namespace

Header parseHeader(const uint8_t* bytes, size_t size) {
    const uint8_t* const end = bytes + size;
    // The first line is "ply"; its ending (LF, CRLF or CR alone) is the
    // header's, so that a CR-only header is not read past its end_header
    // into a binary body starting with byte 10.
    const uint8_t* firstEnd = bytes;
    while (firstEnd < end && (*firstEnd == ' ' || *firstEnd == '\t')) ++firstEnd;
    if (end - firstEnd < 3 || std::memcmp(firstEnd, "ply", 3) != 0) throw invalid("not a PLY file: it does not start with \"ply\"");
    firstEnd += 3;
    while (firstEnd < end && (*firstEnd == ' ' || *firstEnd == '\t')) ++firstEnd;
    if (firstEnd < end && *firstEnd != '\n' && *firstEnd != '\r') throw invalid("not a PLY file: it does not start with \"ply\"");
    const bool crOnly = firstEnd < end && *firstEnd == '\r' && (firstEnd + 1 == end || firstEnd[1] != '\n');
    const uint8_t terminator = crOnly ? '\r' : '\n';

    Header header;
    // Sets, not searches: a hostile header may hold a million names.
    std::set<int> knownKinds;
    std::set<std::string> propertyNames;  // the last element's
    bool sawFormat = false, sawEnd = false;
    size_t lineNumber = 1;
    const uint8_t* line = firstEnd;
    {
        const void* stop = line < end ? std::memchr(line, terminator, size_t(end - line)) : nullptr;
        line = stop ? static_cast<const uint8_t*>(stop) + 1 : end;
    }
    while (line < end && !sawEnd) {
        const void* found = std::memchr(line, terminator, size_t(end - line));
        const uint8_t* stop = found ? static_cast<const uint8_t*>(found) : end;
        const uint8_t* textEnd = stop;
        if (!crOnly && textEnd > line && textEnd[-1] == '\r') --textEnd;
        const uint8_t* next = found ? stop + 1 : end;
        ++lineNumber;
        const std::string where = "header line " + std::to_string(lineNumber);

        const uint8_t* keywordStart = line;
        while (keywordStart < textEnd && isBlank(*keywordStart)) ++keywordStart;
        const uint8_t* keywordEnd = keywordStart;
        while (keywordEnd < textEnd && !isBlank(*keywordEnd)) ++keywordEnd;
        const std::string keyword(reinterpret_cast<const char*>(keywordStart), size_t(keywordEnd - keywordStart));
        line = next;
        if (keyword.empty()) continue;
        if (keyword == "comment" || keyword == "obj_info") {
            const uint8_t* text = keywordEnd;
            while (text < textEnd && (*text == ' ' || *text == '\t')) ++text;
            // Only comments that can mean something are copied: a header
            // may hold megabytes of others.
            const size_t length = size_t(textEnd - text);
            if ((length >= 11 && std::memcmp(text, "TextureFile", 11) == 0) || (length >= 8 && std::memcmp(text, "num_", 4) == 0))
                readCommentText(std::string(reinterpret_cast<const char*>(text), size_t(textEnd - text)), header);
            continue;
        }
        const std::vector<std::string> tokens = splitBlanks(keywordStart, textEnd);
        if (keyword == "format") {
            if (tokens.size() < 2) throw invalid(where + ": format without a name");
            if (tokens[1] == "ascii") header.encoding = Encoding::Ascii;
            else if (tokens[1] == "binary_little_endian") header.encoding = Encoding::LittleEndian;
            else if (tokens[1] == "binary_big_endian") header.encoding = Encoding::BigEndian;
            else throw invalid(where + ": unknown format '" + tokens[1] + "'");
            sawFormat = true;
        } else if (keyword == "element") {
            if (tokens.size() != 3) throw invalid(where + ": expected 'element NAME COUNT'");
            errno = 0;
            char* endOfNumber = nullptr;
            const long long count = std::strtoll(tokens[2].c_str(), &endOfNumber, 10);
            if (*endOfNumber != '\0' || errno != 0 || count < 0 || count > 0x7FFFFFFF)
                throw invalid(where + ": bad element count '" + tokens[2] + "'");
            Element element;
            element.name = tokens[1];
            element.count = uint64_t(count);
            element.kind = kindOf(element.name);
            if (element.kind != Kind::Other && !knownKinds.insert(int(element.kind)).second)
                throw invalid(where + ": a second '" + element.name + "' element");
            header.elements.push_back(element);
            propertyNames.clear();
        } else if (keyword == "property") {
            if (header.elements.empty()) throw invalid(where + ": property before any element");
            Property property;
            if (tokens.size() == 5 && tokens[1] == "list") {
                property.list = true;
                if (!scalarNamed(tokens[2], property.countType)) throw invalid(where + ": unknown type '" + tokens[2] + "'");
                if (!scalarNamed(tokens[3], property.type)) throw invalid(where + ": unknown type '" + tokens[3] + "'");
                if (!describe(property.countType).integer)
                    throw invalid(where + ": a list's count must have an integer type, not '" + tokens[2] + "'");
                property.name = tokens[4];
            } else if (tokens.size() == 3 && tokens[1] != "list") {
                if (!scalarNamed(tokens[1], property.type)) throw invalid(where + ": unknown type '" + tokens[1] + "'");
                property.name = tokens[2];
            } else {
                throw invalid(where + ": expected 'property TYPE NAME' or 'property list COUNT ITEM NAME'");
            }
            Element& element = header.elements.back();
            if (!propertyNames.insert(property.name).second)
                throw invalid(where + ": element '" + element.name + "' has a second property '" + property.name + "'");
            element.properties.push_back(property);
        } else if (keyword == "end_header") {
            sawEnd = true;
            header.bodyStart = size_t(next - bytes);
        } else {
            throw invalid(where + ": unknown keyword '" + keyword + "'");
        }
    }
    if (!sawEnd) throw invalid("the header has no end_header line");
    if (!sawFormat) throw invalid("the header names no format");
    return header;
}

}  // namespace ply
}  // namespace vcgio
}  // namespace drm
