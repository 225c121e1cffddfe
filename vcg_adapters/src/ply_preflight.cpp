// preflightPly: see format_preflight.h for why. The file's header is parsed
// and its body walked element by element, item by item, as vcglib's plylib
// will read it; lists vcglib copies into fixed-size arrays are bounded and
// face indices checked before vcglib sees the file.
#include "format_preflight.h"

#include <drm/drm.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace drm {
namespace vcgio {

namespace {

enum class Encoding { Ascii, LittleEndian, BigEndian };

struct ScalarType {
    const char* names[2];
    int size;
    bool integer;
    bool isSigned;
};

const ScalarType kTypes[] = {
    {{"char", "int8"}, 1, true, true},       {{"uchar", "uint8"}, 1, true, false},
    {{"short", "int16"}, 2, true, true},     {{"ushort", "uint16"}, 2, true, false},
    {{"int", "int32"}, 4, true, true},       {{"uint", "uint32"}, 4, true, false},
    {{"float", "float32"}, 4, false, true},  {{"double", "float64"}, 8, false, true},
};

const ScalarType* typeNamed(const std::string& name) {
    for (const ScalarType& type : kTypes)
        if (name == type.names[0] || name == type.names[1]) return &type;
    return nullptr;
}

struct Property {
    std::string name;
    const ScalarType* type = nullptr;
    const ScalarType* countType = nullptr;  // non-null for lists
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

std::vector<std::string> splitBlanks(const std::string& line) {
    std::vector<std::string> tokens;
    size_t from = 0;
    while (from < line.size()) {
        while (from < line.size() && std::strchr(" \t\r", line[from])) ++from;
        size_t to = from;
        while (to < line.size() && !std::strchr(" \t\r", line[to])) ++to;
        if (to > from) tokens.push_back(line.substr(from, to - from));
        from = to;
    }
    return tokens;
}

// Reads scalars from the body in the file's encoding.
class BodyReader {
public:
    BodyReader(const std::vector<uint8_t>& bytes, size_t start, Encoding encoding)
        : bytes_(bytes), position_(start), encoding_(encoding) {}

    size_t bytesLeft() const { return bytes_.size() - position_; }
    bool binary() const { return encoding_ != Encoding::Ascii; }
    void advance(size_t bytes) { position_ += bytes; }  // at most bytesLeft()

    // False at the end of the data.
    bool skip(const ScalarType& type) {
        if (encoding_ == Encoding::Ascii) return nextToken().size() > 0;
        if (bytesLeft() < size_t(type.size)) return false;
        position_ += size_t(type.size);
        return true;
    }

    // An integer-typed scalar's value. False at the end of the data or when
    // an ASCII token is not an integer.
    bool readInteger(const ScalarType& type, int64_t& value) {
        if (encoding_ == Encoding::Ascii) {
            const std::string token = nextToken();
            if (token.empty()) return false;
            errno = 0;
            char* end = nullptr;
            value = std::strtoll(token.c_str(), &end, 10);
            return end != token.c_str() && *end == '\0' && errno == 0;
        }
        if (bytesLeft() < size_t(type.size)) return false;
        const uint8_t* at = bytes_.data() + position_;
        uint64_t bits = 0;
        if (encoding_ == Encoding::LittleEndian && type.size == 4) {
            // Face corners, nearly always: shifts the compiler turns into one
            // load on a little-endian machine (the loop below cost igea's
            // check about 50 M instructions).
            bits = uint64_t(at[0]) | uint64_t(at[1]) << 8 | uint64_t(at[2]) << 16 | uint64_t(at[3]) << 24;
        } else {
            for (int i = 0; i < type.size; ++i) {
                const int byte = encoding_ == Encoding::LittleEndian ? i : type.size - 1 - i;
                bits |= uint64_t(at[byte]) << (8 * i);
            }
        }
        position_ += size_t(type.size);
        if (type.isSigned && type.size < 8 && (bits >> (8 * type.size - 1)) & 1) bits |= ~uint64_t(0) << (8 * type.size);
        value = int64_t(bits);
        return true;
    }

private:
    std::string nextToken() {
        while (position_ < bytes_.size() && std::strchr(" \t\r\n\f\v", char(bytes_[position_])) && bytes_[position_])
            ++position_;
        const size_t start = position_;
        while (position_ < bytes_.size() && bytes_[position_] && !std::strchr(" \t\r\n\f\v", char(bytes_[position_])))
            ++position_;
        return std::string(bytes_.begin() + long(start), bytes_.begin() + long(position_));
    }

    const std::vector<uint8_t>& bytes_;
    size_t position_;
    Encoding encoding_;
};

// The most entries vcglib's fixed arrays take for a list it reads, or 0 for
// no limit (lists it skips or allocates).
int64_t listLimit(const std::string& element, const std::string& property) {
    if (element == "face" && (property == "vertex_indices" || property == "vertex_index"))
        return 127;  // some of vcglib's face descriptors store the count in a signed char
    if (element == "face" && (property == "texcoord" || property == "color")) return 32;
    if (element == "range_grid" && property == "vertex_indices") return 5;
    return 0;
}

// Whether the header describes PlainPly's layout (the body not yet checked).
bool plainLayout(Encoding encoding, const std::vector<Element>& elements) {
    if (encoding != Encoding::LittleEndian || elements.size() != 2) return false;
    const Element& vertex = elements[0];
    const Element& face = elements[1];
    if (vertex.name != "vertex" || vertex.properties.size() != 3 || face.name != "face" || face.properties.size() != 1)
        return false;
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        const Property& p = vertex.properties[size_t(k)];
        if (p.name != axes[k] || p.countType || p.type->integer || p.type->size != 4) return false;
    }
    const Property& corners = face.properties[0];
    return corners.name == "vertex_indices" && corners.countType && corners.countType->size == 1 &&
           !corners.countType->isSigned && corners.type->integer && corners.type->size == 4;
}

}  // namespace

int64_t preflightPly(const std::vector<uint8_t>& bytes, std::vector<std::string>* properties, PlainPly* plain) {
    // Header: lines up to "end_header".
    const std::string marker = "end_header";
    size_t position = 0, lineNumber = 0;
    Encoding encoding = Encoding::Ascii;
    bool sawFormat = false, sawEnd = false;
    std::vector<Element> elements;
    while (position < bytes.size() && !sawEnd) {
        size_t end = position;
        while (end < bytes.size() && bytes[end] != '\n') ++end;
        const std::string line(bytes.begin() + long(position), bytes.begin() + long(end));
        position = end + 1;
        ++lineNumber;
        const std::vector<std::string> tokens = splitBlanks(line);
        const std::string where = "header line " + std::to_string(lineNumber);
        if (lineNumber == 1) {
            if (tokens.size() != 1 || tokens[0] != "ply") throw Error(ErrorKind::InvalidInput, "not a PLY file: it does not start with \"ply\"");
            continue;
        }
        if (tokens.empty() || tokens[0] == "comment" || tokens[0] == "obj_info") continue;
        if (tokens[0] == "format") {
            if (tokens.size() < 2) throw Error(ErrorKind::InvalidInput, where + ": format without a name");
            if (tokens[1] == "ascii") encoding = Encoding::Ascii;
            else if (tokens[1] == "binary_little_endian") encoding = Encoding::LittleEndian;
            else if (tokens[1] == "binary_big_endian") encoding = Encoding::BigEndian;
            else throw Error(ErrorKind::InvalidInput, where + ": unknown format '" + tokens[1] + "'");
            sawFormat = true;
        } else if (tokens[0] == "element") {
            if (tokens.size() != 3) throw Error(ErrorKind::InvalidInput, where + ": expected 'element NAME COUNT'");
            errno = 0;
            char* endOfNumber = nullptr;
            const long long count = std::strtoll(tokens[2].c_str(), &endOfNumber, 10);
            if (*endOfNumber != '\0' || errno != 0 || count < 0 || count > 0x7FFFFFFF)
                throw Error(ErrorKind::InvalidInput, where + ": bad element count '" + tokens[2] + "'");
            elements.push_back(Element{tokens[1], uint64_t(count), {}});
        } else if (tokens[0] == "property") {
            if (elements.empty()) throw Error(ErrorKind::InvalidInput, where + ": property before any element");
            Property property;
            if (tokens.size() == 5 && tokens[1] == "list") {
                property.countType = typeNamed(tokens[2]);
                property.type = typeNamed(tokens[3]);
                property.name = tokens[4];
                if (!property.countType || !property.countType->integer || !property.type)
                    throw Error(ErrorKind::InvalidInput, where + ": bad list types '" + tokens[2] + " " + tokens[3] + "'");
            } else if (tokens.size() == 3) {
                property.type = typeNamed(tokens[1]);
                property.name = tokens[2];
                if (!property.type) throw Error(ErrorKind::InvalidInput, where + ": unknown type '" + tokens[1] + "'");
            } else {
                throw Error(ErrorKind::InvalidInput, where + ": expected 'property TYPE NAME' or 'property list COUNT ITEM NAME'");
            }
            elements.back().properties.push_back(property);
        } else if (tokens[0] == marker) {
            sawEnd = true;
        } else {
            throw Error(ErrorKind::InvalidInput, where + ": unknown keyword '" + tokens[0] + "'");
        }
    }
    if (!sawEnd) throw Error(ErrorKind::InvalidInput, "the header has no end_header line");
    if (!sawFormat) throw Error(ErrorKind::InvalidInput, "the header names no format");
    if (properties)
        for (const Element& element : elements)
            for (const Property& property : element.properties) properties->push_back(element.name + "." + property.name);

    // Body: every element in header order.
    int64_t vertexCount = 0;
    for (const Element& element : elements)
        if (element.name == "vertex") vertexCount = int64_t(element.count);
    BodyReader body(bytes, position, encoding);
    int64_t triangles = -1;
    for (const Element& element : elements) {
        // Every item takes at least a byte; a count beyond that cannot be
        // real and would only make the reader allocate wildly.
        if (element.count > body.bytesLeft())
            throw Error(ErrorKind::InvalidInput, "the header's " + element.name + " count " + std::to_string(element.count) +
                        " does not fit in the file");
        if (element.properties.empty() && element.count > 0)
            throw Error(ErrorKind::InvalidInput, "element '" + element.name + "' has items but no properties");
        // Per property, once: the limit on its list's entries (name
        // compares per item cost igea's check 140 M instructions).
        std::vector<int64_t> limits;
        for (const Property& property : element.properties) limits.push_back(listLimit(element.name, property.name));
        // Binary items of scalars alone (vertices, mostly) all have one
        // size: only that they fit needs checking, not each item.
        size_t itemSize = 0;
        bool scalarsOnly = body.binary();
        for (const Property& property : element.properties) {
            scalarsOnly = scalarsOnly && !property.countType;
            itemSize += size_t(property.type->size);
        }
        if (scalarsOnly && itemSize > 0) {
            const uint64_t fit = body.bytesLeft() / itemSize;  // itemSize > 0: the element has properties
            if (element.count > fit)
                throw Error(ErrorKind::InvalidInput,
                            "the file ends inside " + element.name + " " + std::to_string(fit) + " (truncated?)");
            body.advance(size_t(element.count) * itemSize);
            continue;
        }
        for (uint64_t item = 0; item < element.count; ++item) {
            // Named only for a message: building it per item cost as much again.
            const auto where = [&] { return element.name + " " + std::to_string(item); };
            for (size_t p = 0; p < element.properties.size(); ++p) {
                const Property& property = element.properties[p];
                if (!property.countType) {
                    if (!body.skip(*property.type)) throw Error(ErrorKind::InvalidInput, "the file ends inside " + where() + " (truncated?)");
                    continue;
                }
                int64_t entries = 0;
                if (!body.readInteger(*property.countType, entries))
                    throw Error(ErrorKind::InvalidInput, "the file ends inside " + where() + " (truncated?)");
                const int64_t limit = limits[p];
                const bool cornerList = limit == 127;
                if (cornerList && triangles < 0) triangles = 0;
                if (entries < 0 || (limit > 0 && entries > limit) || (cornerList && entries < 3))
                    throw Error(ErrorKind::InvalidInput, where() + " has " + std::to_string(entries) + " " + property.name + " entries" +
                                (cornerList ? " (faces need 3 to 127 corners)" : ""));
                if (uint64_t(entries) > body.bytesLeft()) throw Error(ErrorKind::InvalidInput, "the file ends inside " + where() + " (truncated?)");
                if (cornerList) triangles += entries - 2;
                for (int64_t i = 0; i < entries; ++i) {
                    if (!cornerList) {
                        if (!body.skip(*property.type)) throw Error(ErrorKind::InvalidInput, "the file ends inside " + where() + " (truncated?)");
                        continue;
                    }
                    int64_t index = 0;
                    if (!property.type->integer || !body.readInteger(*property.type, index))
                        throw Error(ErrorKind::InvalidInput, where() + ": its corners are not integer vertex indices (or the file ends)");
                    if (index < 0 || index >= vertexCount)
                        throw Error(ErrorKind::InvalidInput, where() + " refers to vertex " + std::to_string(index) + ", but the file has " +
                                    std::to_string(vertexCount) + " vertices");
                }
            }
        }
    }
    if (plain) {
        *plain = PlainPly();
        // Every face a triangle: then the faces make as many triangles.
        if (plainLayout(encoding, elements) && triangles >= 0 && uint64_t(triangles) == elements[1].count) {
            plain->plain = true;
            plain->vertexCount = elements[0].count;
            plain->faceCount = elements[1].count;
            plain->vertexStart = position;
            plain->faceStart = position + 12 * size_t(plain->vertexCount);
        }
    }
    return triangles;
}

}  // namespace vcgio
}  // namespace drm
