// readPly: see ply_reader.h. The header is parsed into elements whose
// properties each get a role (what of drm::Mesh they fill); the body is
// then read element by element in the file's order. Binary elements of
// scalars alone (vertices, nearly always) are read a property at a time down
// the whole element, one loop per property compiled for its type and byte
// order; faces whose only property is a uchar-counted list of 4-byte
// indices (nearly every mesh file) have a loop of their own; everything
// else, and every ASCII file, is read item by item.
#include "ply_reader.h"

#include "text_lines.h"

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <set>

namespace drm {
namespace vcgio {

namespace {

Error invalid(const std::string& message) { return Error(ErrorKind::InvalidInput, message); }

// ---------------------------------------------------------------- types

enum class Scalar : uint8_t { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

struct ScalarName {
    const char* name;
    const char* alias;
    size_t size;
    bool integer;
};

const ScalarName kScalars[] = {
    {"char", "int8", 1, true},      {"uchar", "uint8", 1, true},  {"short", "int16", 2, true},
    {"ushort", "uint16", 2, true},  {"int", "int32", 4, true},    {"uint", "uint32", 4, true},
    {"float", "float32", 4, false}, {"double", "float64", 8, false},
};

const ScalarName& describe(Scalar type) { return kScalars[size_t(type)]; }
unsigned bitOf(Scalar type) { return 1u << unsigned(type); }

bool scalarNamed(const std::string& text, Scalar& type) {
    for (size_t i = 0; i < sizeof kScalars / sizeof kScalars[0]; ++i)
        if (text == kScalars[i].name || text == kScalars[i].alias) {
            type = Scalar(i);
            return true;
        }
    return false;
}

// "double", "int and double": the types whose bits are set.
std::string typeList(unsigned types) {
    std::vector<std::string> names;
    for (size_t i = 0; i < sizeof kScalars / sizeof kScalars[0]; ++i)
        if (types & (1u << i)) names.push_back(kScalars[i].name);
    return joinList(names);
}

// Calls fn(T()) with T the C++ type of `type`: fn's body is compiled once
// per type, so that a loop inside it needs no type switch per value.
template <class Fn>
void withType(Scalar type, Fn&& fn) {
    switch (type) {
    case Scalar::Int8: fn(int8_t()); break;
    case Scalar::Uint8: fn(uint8_t()); break;
    case Scalar::Int16: fn(int16_t()); break;
    case Scalar::Uint16: fn(uint16_t()); break;
    case Scalar::Int32: fn(int32_t()); break;
    case Scalar::Uint32: fn(uint32_t()); break;
    case Scalar::Float32: fn(float()); break;
    case Scalar::Float64: fn(double()); break;
    }
}

// A value as a message shows it.
template <class I> std::string show(I value) { return std::to_string(int64_t(value)); }
std::string show(uint32_t value) { return std::to_string(value); }
std::string show(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}
std::string show(float value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", double(value));
    return text;
}

// ---------------------------------------------------------------- conversions

// How a group of values (positions, say) came to be floats: how many were
// rounded, and from which types, for the note.
struct FloatStats {
    size_t changed = 0;
    unsigned sourceTypes = 0;  // bits of the types other than float
};

// How a group of colour values came to be bytes.
struct ColourStats {
    unsigned scaledTypes = 0;   // float, double (0..1) and ushort (0..65535) scale
    size_t clampedUnit = 0;     // float values outside 0..1
    size_t clampedInteger = 0;  // integer values outside 0..255
    bool grey = false;          // read from `intensity`
};

// False if a double is beyond float's range (the conversion would be
// undefined, and infinity is not the file's value).
inline bool toFloat(float value, float& out, FloatStats&) {
    out = value;
    return true;
}
inline bool toFloat(double value, float& out, FloatStats& stats) {
    if (std::isfinite(value) && std::fabs(value) > double(FLT_MAX)) return false;
    out = float(value);
    if (double(out) != value && !std::isnan(value)) ++stats.changed;
    return true;
}
template <class I>
inline bool toFloat(I value, float& out, FloatStats& stats) {
    out = float(value);
    if (double(out) != double(value)) ++stats.changed;
    return true;
}

inline uint8_t unitToByte(double value, ColourStats& stats) {
    if (!(value >= 0.0)) {  // negative or NaN
        ++stats.clampedUnit;
        return 0;
    }
    if (value > 1.0) {
        ++stats.clampedUnit;
        return 255;
    }
    return uint8_t(std::lround(value * 255.0));
}
inline uint8_t toByte(uint8_t value, ColourStats&) { return value; }
inline uint8_t toByte(float value, ColourStats& stats) { return unitToByte(double(value), stats); }
inline uint8_t toByte(double value, ColourStats& stats) { return unitToByte(value, stats); }
inline uint8_t toByte(uint16_t value, ColourStats&) { return uint8_t((uint32_t(value) * 255u + 32767u) / 65535u); }
template <class I>
inline uint8_t toByte(I value, ColourStats& stats) {
    const int64_t wide = int64_t(value);
    if (wide < 0 || wide > 255) {
        ++stats.clampedInteger;
        return wide < 0 ? 0 : 255;
    }
    return uint8_t(wide);
}

// A whole number (vertex index, texture number, list count), or kNotWhole.
constexpr int64_t kNotWhole = std::numeric_limits<int64_t>::min();
template <class I>
inline int64_t toWhole(I value) {
    return int64_t(value);
}
inline int64_t toWhole(double value) {
    return (value == std::floor(value) && std::fabs(value) < 9.0e18) ? int64_t(value) : kNotWhole;
}
inline int64_t toWhole(float value) { return toWhole(double(value)); }

// ---------------------------------------------------------------- header

enum class Encoding { Ascii, LittleEndian, BigEndian };

// What a property's values become.
enum class Role : uint8_t {
    Other,            // read past; named in otherProperties
    Dropped,          // read past; named in dropped (face normals, radii, ...)
    Position,         // component 0..2
    Normal,           // component 0..2
    Colour,           // component 0..3 (red, green, blue, alpha)
    Grey,             // intensity: red, green and blue at once
    TexCoord,         // component 0..1
    Quality,
    Corners,          // face list: vertex indices
    CornerTexCoords,  // face list: u, v per corner
    TexNumber,
    FaceColour,       // component 0..3
    FaceQuality,
    Strip,            // tristrips list: vertex indices, -1 between strips
    GridCell,         // range_grid list: no entry, or the cell's vertex
};

struct Property {
    std::string name;
    Scalar type = Scalar::Float32;
    bool list = false;
    Scalar countType = Scalar::Uint8;
    Role role = Role::Other;
    size_t component = 0;
};

enum class Kind { Vertex, Face, Tristrips, RangeGrid, Other };

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
    Kind kind = Kind::Other;
};

struct Header {
    Encoding encoding = Encoding::Ascii;
    std::vector<Element> elements;
    std::vector<std::string> textures;      // `comment TextureFile NAME`, in order
    int64_t gridColumns = -1, gridRows = -1;  // `obj_info num_cols N`, `num_rows N`
    size_t bodyStart = 0;
};

bool isBlank(uint8_t c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

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

// ---------------------------------------------------------------- roles

Property* scalarProperty(Element& element, const char* name) {
    for (Property& p : element.properties)
        if (!p.list && p.name == name && p.role == Role::Other) return &p;
    return nullptr;
}

Property* listProperty(Element& element, const char* name) {
    for (Property& p : element.properties)
        if (p.list && p.name == name && p.role == Role::Other) return &p;
    return nullptr;
}

// Gives the scalars `names` the role, as components 0, 1, ..., if the
// element has them all (and none has a role yet).
bool assignAll(Element& element, std::initializer_list<const char*> names, Role role) {
    std::vector<Property*> found;
    for (const char* name : names) {
        Property* p = scalarProperty(element, name);
        if (!p) return false;
        found.push_back(p);
    }
    for (size_t i = 0; i < found.size(); ++i) {
        found[i]->role = role;
        found[i]->component = i;
    }
    return true;
}

bool assignOne(Property* p, Role role, size_t component = 0) {
    if (!p) return false;
    p->role = role;
    p->component = component;
    return true;
}

// What each property becomes; what is not kept goes into `out`'s lists.
void assignRoles(Header& header, PlyContents& out) {
    bool faceNormals = false, cornerColours = false, radii = false, edges = false, camera = false;
    for (Element& e : header.elements) {
        if (e.kind == Kind::Vertex) {
            const char* const axes[3] = {"x", "y", "z"};
            std::vector<std::string> missing;
            for (size_t k = 0; k < 3; ++k)
                if (!assignOne(scalarProperty(e, axes[k]), Role::Position, k)) missing.push_back(axes[k]);
            if (!missing.empty())
                throw invalid("the vertex element has no " + joinList(missing) + (missing.size() == 1 ? " property" : " properties"));
            assignAll(e, {"nx", "ny", "nz"}, Role::Normal);
            if (assignAll(e, {"red", "green", "blue"}, Role::Colour)) assignOne(scalarProperty(e, "alpha"), Role::Colour, 3);
            else if (assignAll(e, {"diffuse_red", "diffuse_green", "diffuse_blue"}, Role::Colour))
                assignOne(scalarProperty(e, "diffuse_alpha"), Role::Colour, 3);
            else assignOne(scalarProperty(e, "intensity"), Role::Grey);
            if (!assignOne(scalarProperty(e, "quality"), Role::Quality)) assignOne(scalarProperty(e, "confidence"), Role::Quality);
            if (!assignAll(e, {"texture_u", "texture_v"}, Role::TexCoord) && !assignAll(e, {"s", "t"}, Role::TexCoord))
                assignAll(e, {"u", "v"}, Role::TexCoord);
            radii = assignOne(scalarProperty(e, "radius"), Role::Dropped) && e.count > 0;
        } else if (e.kind == Kind::Face) {
            if (!assignOne(listProperty(e, "vertex_indices"), Role::Corners) && !assignOne(listProperty(e, "vertex_index"), Role::Corners))
                continue;  // no corners: nothing else on a face can be kept
            assignOne(listProperty(e, "texcoord"), Role::CornerTexCoords);
            assignOne(scalarProperty(e, "texnumber"), Role::TexNumber);
            if (assignAll(e, {"red", "green", "blue"}, Role::FaceColour)) assignOne(scalarProperty(e, "alpha"), Role::FaceColour, 3);
            assignOne(scalarProperty(e, "quality"), Role::FaceQuality);
            faceNormals = assignAll(e, {"nx", "ny", "nz"}, Role::Dropped) && e.count > 0;
            cornerColours = assignOne(listProperty(e, "color"), Role::Dropped) && e.count > 0;
        } else if (e.kind == Kind::Tristrips) {
            assignOne(listProperty(e, "vertex_indices"), Role::Strip);
        } else if (e.kind == Kind::RangeGrid && header.gridColumns > 0 && header.gridRows > 0) {
            // Without the grid's size its cells make no faces (and are named).
            assignOne(listProperty(e, "vertex_indices"), Role::GridCell);
        }
    }
    for (const Element& e : header.elements) {
        if (e.count == 0) continue;
        if (e.kind == Kind::Other) {
            if (e.name == "edge") edges = true;
            else if (e.name == "camera") camera = true;
            else out.otherElements.push_back(e.name);
            continue;
        }
        for (const Property& p : e.properties)
            if (p.role == Role::Other) out.otherProperties.push_back(e.name + "." + p.name);
    }
    // In the order and words loadMesh uses for every format.
    if (faceNormals) out.dropped.push_back("per-face normals");
    if (cornerColours) out.dropped.push_back("per-corner colours");
    if (radii) out.dropped.push_back("vertex radii");
    if (edges) out.dropped.push_back("edges");
    if (camera) out.dropped.push_back("camera parameters");
}

// ---------------------------------------------------------------- cursors

#if defined(__BYTE_ORDER__) && defined(__ORDER_BIG_ENDIAN__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
constexpr bool kHostBigEndian = true;
#else
constexpr bool kHostBigEndian = false;
#endif

template <class T, bool BigEndian>
inline T load(const uint8_t* at) {
    T value;
    if (BigEndian == kHostBigEndian) {
        std::memcpy(&value, at, sizeof(T));
    } else {
        uint8_t swapped[sizeof(T)];
        for (size_t i = 0; i < sizeof(T); ++i) swapped[i] = at[sizeof(T) - 1 - i];
        std::memcpy(&value, swapped, sizeof(T));
    }
    return value;
}

enum class ReadStatus { Ok, End, Bad };

template <bool BigEndian>
class BinaryCursor {
public:
    BinaryCursor(const uint8_t* at, const uint8_t* end) : at_(at), end_(end) {}
    template <class T>
    ReadStatus read(T& value) {
        if (size_t(end_ - at_) < sizeof(T)) return ReadStatus::End;
        value = load<T, BigEndian>(at_);
        at_ += sizeof(T);
        return ReadStatus::Ok;
    }
    ReadStatus readCount(Scalar type, int64_t& entries) {
        ReadStatus status = ReadStatus::Ok;
        withType(type, [&](auto tag) {
            decltype(tag) value{};
            status = this->read(value);
            entries = toWhole(value);
        });
        return status;
    }
    size_t bytesLeft() const { return size_t(end_ - at_); }
    // The fewest bytes a list entry of `type` takes.
    static size_t entryBytes(Scalar type) { return describe(type).size; }
    std::string problem() const { return ""; }

private:
    const uint8_t* at_;
    const uint8_t* end_;
};

// ASCII values: blank-separated tokens, wherever the lines break. Floats are
// parsed by strtof (float) or strtod (double), as the header types them;
// integers must be whole numbers in their type's range.
class AsciiCursor {
public:
    AsciiCursor(const uint8_t* at, const uint8_t* end) : at_(at), end_(end) {}
    template <class T>
    ReadStatus read(T& value) {
        while (at_ < end_ && isBlank(*at_)) ++at_;
        if (at_ == end_) return ReadStatus::End;
        const uint8_t* start = at_;
        while (at_ < end_ && !isBlank(*at_)) ++at_;
        token_.assign(reinterpret_cast<const char*>(start), size_t(at_ - start));
        return parse(value) ? ReadStatus::Ok : ReadStatus::Bad;
    }
    // Any whole number: the count's type gives its width in binary files
    // only, and a count beyond the file is refused as such.
    ReadStatus readCount(Scalar, int64_t& entries) { return read(entries); }
    size_t bytesLeft() const { return size_t(end_ - at_); }
    // A blank and a character at least.
    static size_t entryBytes(Scalar) { return 2; }
    // Why the last token was refused: "'abc' is not a number".
    std::string problem() const {
        const std::string shown = token_.size() > 40 ? token_.substr(0, 40) + "..." : token_;
        return "'" + shown + "' " + why_;
    }

private:
    bool parse(float& value) {
        char* stop = nullptr;
        value = std::strtof(token_.c_str(), &stop);
        why_ = "is not a number";
        return stop == token_.c_str() + token_.size();
    }
    bool parse(double& value) {
        char* stop = nullptr;
        value = std::strtod(token_.c_str(), &stop);
        why_ = "is not a number";
        return stop == token_.c_str() + token_.size();
    }
    template <class I>
    bool parse(I& value) {
        errno = 0;
        char* stop = nullptr;
        long long whole = std::strtoll(token_.c_str(), &stop, 10);
        if (stop != token_.c_str() + token_.size() || errno != 0) {
            // "3.0" for an integer is still 3.
            const double number = std::strtod(token_.c_str(), &stop);
            if (stop != token_.c_str() + token_.size() || toWhole(number) == kNotWhole) {
                why_ = "is not a whole number";
                return false;
            }
            whole = toWhole(number);
        }
        if (whole < static_cast<long long>(std::numeric_limits<I>::min()) || whole > static_cast<long long>(std::numeric_limits<I>::max())) {
            why_ = std::string("is outside the range of ") + typeName(I());
            return false;
        }
        value = I(whole);
        return true;
    }

    static const char* typeName(int8_t) { return "char"; }
    static const char* typeName(uint8_t) { return "uchar"; }
    static const char* typeName(int16_t) { return "short"; }
    static const char* typeName(uint16_t) { return "ushort"; }
    static const char* typeName(int32_t) { return "int"; }
    static const char* typeName(uint32_t) { return "uint"; }
    static const char* typeName(int64_t) { return "a count"; }

    const uint8_t* at_;
    const uint8_t* end_;
    std::string token_;
    std::string why_;
};

// ---------------------------------------------------------------- body

class BodyReader {
public:
    BodyReader(const Header& header, PlyContents& out) : header_(header), out_(out) {
        for (const Element& e : header.elements)
            if (e.kind == Kind::Vertex) vertexCount_ = e.count;
    }

    void read(const uint8_t* bytes, size_t size) {
        const uint8_t* at = bytes + header_.bodyStart;
        const uint8_t* const end = bytes + size;
        for (const Element& e : header_.elements) {
            element_ = &e;
            begin(e, size_t(end - at));
            if (header_.encoding == Encoding::Ascii) {
                AsciiCursor cursor(at, end);
                readItems(cursor, e);
                at = end - cursor.bytesLeft();
            } else if (header_.encoding == Encoding::LittleEndian) {
                at = readBinary<false>(at, end, e);
            } else {
                at = readBinary<true>(at, end, e);
            }
            finish(e);
        }
        // Data past the last element the header declares (more faces than
        // its count, say) is not read: say so rather than drop it quietly.
        size_t trailing = size_t(end - at);
        if (header_.encoding == Encoding::Ascii)
            trailing = size_t(std::count_if(at, end, [](uint8_t c) { return !isBlank(c) && c != 0; }));
        if (trailing > 0)
            out_.conversions.push_back("the file goes on past the last element its header declares: " +
                                       std::to_string(trailing) + (header_.encoding == Encoding::Ascii ? " characters" : " bytes") +
                                       " are not read");
        assemble();
    }

private:
    std::string where(uint64_t item) const { return element_->name + " " + std::to_string(item); }
    Error endsInside(uint64_t item) const { return invalid("the file ends inside " + where(item) + " (truncated?)"); }

    // Checks that the element's items fit in the bytes left, then makes room
    // for what they hold.
    void begin(const Element& e, size_t bytesLeft) {
        if (e.count > 0 && e.properties.empty())
            throw invalid("element '" + e.name + "' has items but no properties");
        if (e.count > bytesLeft)
            throw invalid("the header's " + e.name + " count " + std::to_string(e.count) + " does not fit in the file");
        const bool ascii = header_.encoding == Encoding::Ascii;
        uint64_t leastItemBytes = 0;
        bool fixed = !ascii;
        for (const Property& p : e.properties) {
            leastItemBytes += ascii ? 2 : describe(p.list ? p.countType : p.type).size;
            fixed = fixed && !p.list;
        }
        // ASCII: a token and a blank per property, but the file's last token
        // may end it without a blank.
        if (e.count * leastItemBytes > bytesLeft + (ascii ? 1 : 0)) {
            if (fixed) throw endsInside(bytesLeft / leastItemBytes);
            throw invalid("the header's " + e.name + " count " + std::to_string(e.count) +
                          " does not fit in the file (truncated?)");
        }
        if (e.kind == Kind::Vertex) {
            const size_t n = size_t(e.count);
            positions_.assign(3 * n, 0.0f);
            for (const Property& p : e.properties) {
                if (p.role == Role::Normal) normals_.assign(3 * n, 0.0f);
                if (p.role == Role::Colour || p.role == Role::Grey) colours_.assign(4 * n, 255);
                if (p.role == Role::TexCoord) texCoords_.assign(2 * n, 0.0f);
                if (p.role == Role::Quality) quality_.assign(n, 0.0f);
                noteSourceType(p);
            }
        } else if (e.kind == Kind::Face) {
            // A face takes 4 bytes at least (7 in ASCII, 13 in binary).
            triangles_.reserve(triangles_.size() + 3 * size_t(std::min<uint64_t>(e.count, bytesLeft / 4)));
            for (const Property& p : e.properties) {
                if (p.role == Role::CornerTexCoords) faceHasTexCoords_ = true;
                if (p.role == Role::TexNumber) faceHasTexNumber_ = true;
                if (p.role == Role::FaceColour) faceHasColour_ = true;
                if (p.role == Role::FaceQuality) faceHasQuality_ = true;
                noteSourceType(p);
            }
        } else if (e.kind == Kind::RangeGrid) {
            grid_.reserve(size_t(e.count));
        }
    }

    // Which types each group's values come from, for the notes.
    void noteSourceType(const Property& p) {
        const unsigned bit = p.type == Scalar::Float32 ? 0u : bitOf(p.type);
        const bool scaled = !describe(p.type).integer || p.type == Scalar::Uint16;
        switch (p.role) {
        case Role::Position: positionStats_.sourceTypes |= bit; break;
        case Role::Normal: normalStats_.sourceTypes |= bit; break;
        case Role::TexCoord: texCoordStats_.sourceTypes |= bit; break;
        case Role::Quality: qualityStats_.sourceTypes |= bit; break;
        case Role::CornerTexCoords: cornerTexStats_.sourceTypes |= bit; break;
        case Role::FaceQuality: faceQualityStats_.sourceTypes |= bit; break;
        case Role::Colour:
        case Role::Grey:
            if (scaled) colourStats_.scaledTypes |= bitOf(p.type);
            colourStats_.grey = colourStats_.grey || p.role == Role::Grey;
            break;
        case Role::FaceColour:
            if (scaled) faceColourStats_.scaledTypes |= bitOf(p.type);
            break;
        default: break;
        }
    }

    void finish(const Element& e) {
        if (e.kind == Kind::RangeGrid && hasRole(e, Role::GridCell)) triangulateGrid(e);
    }

    // ---- binary

    template <bool BigEndian>
    const uint8_t* readBinary(const uint8_t* at, const uint8_t* end, const Element& e) {
        size_t itemSize = 0;
        bool fixed = true;
        for (const Property& p : e.properties) {
            itemSize += describe(p.type).size;
            fixed = fixed && !p.list;
        }
        if (fixed) {  // begin() checked that the items fit
            bool any = false;
            for (const Property& p : e.properties) any = any || p.role != Role::Other;
            if (any && e.kind == Kind::Vertex && e.count > 0) readColumns<BigEndian>(at, itemSize, e);
            return at + size_t(e.count) * itemSize;
        }
        if (e.properties.size() == 1 && e.properties[0].role == Role::Corners &&
            e.properties[0].countType == Scalar::Uint8) {
            if (e.properties[0].type == Scalar::Int32) return readCornerLists<int32_t, BigEndian>(at, end, e);
            if (e.properties[0].type == Scalar::Uint32) return readCornerLists<uint32_t, BigEndian>(at, end, e);
        }
        BinaryCursor<BigEndian> cursor(at, end);
        readItems(cursor, e);
        return end - cursor.bytesLeft();
    }

    // A fixed-size vertex element, a property at a time.
    template <bool BigEndian>
    void readColumns(const uint8_t* base, size_t stride, const Element& e) {
        size_t offset = 0;
        for (const Property& p : e.properties) {
            withType(p.type, [&](auto tag) { this->column<decltype(tag), BigEndian>(base + offset, stride, size_t(e.count), p); });
            offset += describe(p.type).size;
        }
    }

    template <class T, bool BigEndian>
    void column(const uint8_t* at, size_t stride, size_t count, const Property& p) {
        switch (p.role) {
        case Role::Position: floatColumn<T, BigEndian>(at, stride, count, p, &positions_[p.component], 3, positionStats_); break;
        case Role::Normal: floatColumn<T, BigEndian>(at, stride, count, p, &normals_[p.component], 3, normalStats_); break;
        case Role::TexCoord: floatColumn<T, BigEndian>(at, stride, count, p, &texCoords_[p.component], 2, texCoordStats_); break;
        case Role::Quality: floatColumn<T, BigEndian>(at, stride, count, p, quality_.data(), 1, qualityStats_); break;
        case Role::Colour: {
            uint8_t* out = &colours_[p.component];
            for (size_t i = 0; i < count; ++i, at += stride, out += 4) *out = toByte(load<T, BigEndian>(at), colourStats_);
            break;
        }
        case Role::Grey: {
            uint8_t* out = colours_.data();
            for (size_t i = 0; i < count; ++i, at += stride, out += 4)
                out[0] = out[1] = out[2] = toByte(load<T, BigEndian>(at), colourStats_);
            break;
        }
        default: break;
        }
    }

    template <class T, bool BigEndian>
    void floatColumn(const uint8_t* at, size_t stride, size_t count, const Property& p, float* out, size_t outStride,
                     FloatStats& stats) {
        for (size_t i = 0; i < count; ++i, at += stride, out += outStride)
            if (!toFloat(load<T, BigEndian>(at), *out, stats)) beyondFloat(i, p, load<T, BigEndian>(at));
    }

    template <class T>
    [[noreturn]] void beyondFloat(uint64_t item, const Property& p, T value) const {
        throw invalid(where(item) + ": its " + p.name + " " + show(value) + " is beyond the range of float");
    }

    // Faces of a uchar-counted list of 4-byte indices and nothing else.
    template <class Index, bool BigEndian>
    const uint8_t* readCornerLists(const uint8_t* at, const uint8_t* end, const Element& e) {
        const Property& p = e.properties[0];
        size_t used = triangles_.size();
        triangles_.resize(used + 3 * size_t(std::min<uint64_t>(e.count, size_t(end - at) / 13)));
        for (uint64_t f = 0; f < e.count; ++f) {
            if (at == end) throw endsInside(f);
            const size_t n = *at++;
            if (size_t(end - at) < 4 * n) throw listBeyondEnd(f, p, int64_t(n));
            if (n < 3) throw tooFewCorners(f, n);
            if (used + 3 * (n - 2) > triangles_.size()) triangles_.resize(std::max(triangles_.size() * 3 / 2, used + 3 * (n - 2)));
            uint32_t* out = triangles_.data() + used;
            const uint32_t first = checkedCorner(f, load<Index, BigEndian>(at));
            uint32_t previous = checkedCorner(f, load<Index, BigEndian>(at + 4));
            for (size_t i = 2; i < n; ++i) {
                const uint32_t next = checkedCorner(f, load<Index, BigEndian>(at + 4 * i));
                out[0] = first;
                out[1] = previous;
                out[2] = next;
                out += 3;
                previous = next;
            }
            used += 3 * (n - 2);
            if (n > 3) trianglesFromPolygons_ += n - 2;
            at += 4 * n;
        }
        triangles_.resize(used);
        return at;
    }

    template <class Index>
    uint32_t checkedCorner(uint64_t face, Index index) const {
        if (int64_t(index) < 0 || uint64_t(index) >= vertexCount_) badCorner(face, index);
        return uint32_t(index);
    }

    template <class T>
    [[noreturn]] void badCorner(uint64_t face, T index) const {
        throw invalid(where(face) + " refers to vertex " + show(index) + ", but the file has " + std::to_string(vertexCount_) +
                      " vertices");
    }

    Error listBeyondEnd(uint64_t item, const Property& p, int64_t entries) const {
        return invalid(where(item) + " has " + std::to_string(entries) + " " + p.name + " entries: the file ends inside it (truncated?)");
    }
    Error tooFewCorners(uint64_t face, size_t corners) const {
        return invalid(where(face) + " has " + std::to_string(corners) + (corners == 1 ? " corner" : " corners") +
                       " (a face needs at least 3)");
    }

    // ---- item by item

    template <class Cursor>
    void readItems(Cursor& cursor, const Element& e) {
        const bool hasCorners = hasRole(e, Role::Corners), hasGrid = hasRole(e, Role::GridCell);
        for (uint64_t item = 0; item < e.count; ++item) {
            corners_.clear();
            itemTexCoords_.clear();
            strip_.clear();
            cell_ = -1;
            faceColour_[3] = 255;
            for (const Property& p : e.properties) {
                if (!p.list) {
                    ReadStatus status = ReadStatus::Ok;
                    withType(p.type, [&](auto tag) {
                        decltype(tag) value{};
                        status = cursor.read(value);
                        if (status == ReadStatus::Ok) this->scalar(p, item, value);
                    });
                    if (status != ReadStatus::Ok) refuse(cursor, status, item, p);
                    continue;
                }
                int64_t entries = 0;
                ReadStatus status = cursor.readCount(p.countType, entries);
                if (status != ReadStatus::Ok) refuse(cursor, status, item, p);
                if (entries < 0)
                    throw invalid(where(item) + " has " + std::to_string(entries) + " " + p.name + " entries");
                if (uint64_t(entries) > cursor.bytesLeft() / Cursor::entryBytes(p.type)) throw listBeyondEnd(item, p, entries);
                withType(p.type, [&](auto tag) {
                    for (int64_t k = 0; k < entries; ++k) {
                        decltype(tag) value{};
                        status = cursor.read(value);
                        if (status != ReadStatus::Ok) return;
                        this->entry(p, item, value);
                    }
                });
                if (status != ReadStatus::Ok) refuse(cursor, status, item, p);
            }
            if (e.kind == Kind::Face && hasCorners) emitFace(item);
            else if (e.kind == Kind::Tristrips) emitStrips();
            else if (e.kind == Kind::RangeGrid && hasGrid) grid_.push_back(cell_);
        }
    }

    static bool hasRole(const Element& e, Role role) {
        for (const Property& p : e.properties)
            if (p.role == role) return true;
        return false;
    }

    template <class Cursor>
    [[noreturn]] void refuse(const Cursor& cursor, ReadStatus status, uint64_t item, const Property& p) const {
        if (status == ReadStatus::End) throw endsInside(item);
        throw invalid(where(item) + ": its " + p.name + " " + cursor.problem());
    }

    template <class T>
    void scalar(const Property& p, uint64_t item, T value) {
        const size_t i = size_t(item);
        switch (p.role) {
        case Role::Position: putFloat(value, positions_[3 * i + p.component], positionStats_, item, p); break;
        case Role::Normal: putFloat(value, normals_[3 * i + p.component], normalStats_, item, p); break;
        case Role::TexCoord: putFloat(value, texCoords_[2 * i + p.component], texCoordStats_, item, p); break;
        case Role::Quality: putFloat(value, quality_[i], qualityStats_, item, p); break;
        case Role::Colour: colours_[4 * i + p.component] = toByte(value, colourStats_); break;
        case Role::Grey: colours_[4 * i] = colours_[4 * i + 1] = colours_[4 * i + 2] = toByte(value, colourStats_); break;
        case Role::FaceColour: faceColour_[p.component] = toByte(value, faceColourStats_); break;
        case Role::FaceQuality: putFloat(value, faceQuality_, faceQualityStats_, item, p); break;
        case Role::TexNumber: {
            const int64_t number = toWhole(value);
            if (number == kNotWhole || number < int64_t(INT32_MIN) || number > int64_t(UINT32_MAX))
                throw invalid(where(item) + ": its texnumber " + show(value) + " is not a texture number");
            texNumber_ = number;
            break;
        }
        default: break;
        }
    }

    template <class T>
    void putFloat(T value, float& out, FloatStats& stats, uint64_t item, const Property& p) {
        if (!toFloat(value, out, stats)) beyondFloat(item, p, value);
    }

    template <class T>
    void entry(const Property& p, uint64_t item, T value) {
        switch (p.role) {
        case Role::Corners: {
            const int64_t index = toWhole(value);
            if (index < 0 || uint64_t(index) >= vertexCount_) badCorner(item, value);
            corners_.push_back(uint32_t(index));
            break;
        }
        case Role::CornerTexCoords: {
            float f = 0;
            putFloat(value, f, cornerTexStats_, item, p);
            itemTexCoords_.push_back(f);
            break;
        }
        case Role::Strip: {
            const int64_t index = toWhole(value);
            if (index == -1) {
                strip_.push_back(kStripRestart);
                break;
            }
            if (index < 0 || uint64_t(index) >= vertexCount_) badCorner(item, value);
            strip_.push_back(uint32_t(index));
            break;
        }
        case Role::GridCell: {
            if (cell_ != -1) break;  // the first entry is the cell's vertex
            const int64_t index = toWhole(value);
            if (index < 0 || uint64_t(index) >= vertexCount_) badCorner(item, value);
            cell_ = index;
            break;
        }
        default: break;
        }
    }

    // One face of the file: its corners fan-split as (0, i, i + 1), each
    // triangle taking the face's colour, quality and texture number and its
    // corners' texture coordinates.
    void emitFace(uint64_t face) {
        const size_t n = corners_.size();
        if (n < 3) throw tooFewCorners(face, n);
        if (faceHasTexCoords_ && itemTexCoords_.size() != 2 * n)
            throw invalid(where(face) + " has " + std::to_string(itemTexCoords_.size()) + " texcoord values for its " +
                          std::to_string(n) + " corners (two per corner)");
        for (size_t i = 1; i + 1 < n; ++i) {
            const size_t corners[3] = {0, i, i + 1};
            for (size_t k : corners) {
                triangles_.push_back(corners_[k]);
                if (faceHasTexCoords_) {
                    cornerTexCoords_.push_back(itemTexCoords_[2 * k]);
                    cornerTexCoords_.push_back(itemTexCoords_[2 * k + 1]);
                }
            }
            if (faceHasColour_) faceColours_.insert(faceColours_.end(), faceColour_, faceColour_ + 4);
            if (faceHasQuality_) faceQualities_.push_back(faceQuality_);
            if (faceHasTexNumber_) faceTexture_.push_back(uint32_t(uint64_t(texNumber_)));
        }
        if (n > 3) trianglesFromPolygons_ += n - 2;
        if (faceHasTexNumber_ && (texNumber_ < 0 || uint64_t(texNumber_) >= header_.textures.size())) {
            if (texNumbersOutside_ == 0) {
                firstOutsideFace_ = face;
                firstOutsideNumber_ = texNumber_;
            }
            ++texNumbersOutside_;
        }
    }

    // Stanford's triangle strips: -1 starts a new strip; every other
    // triangle of a strip is turned (b, a, c) to keep the orientation.
    void emitStrips() {
        size_t start = 0;
        for (size_t k = 0; k <= strip_.size(); ++k) {
            if (k < strip_.size() && strip_[k] != kStripRestart) continue;
            for (size_t j = start; j + 2 < k; ++j) {
                const bool odd = (j - start) % 2 == 1;
                triangles_.push_back(strip_[odd ? j + 1 : j]);
                triangles_.push_back(strip_[odd ? j : j + 1]);
                triangles_.push_back(strip_[j + 2]);
            }
            start = k + 1;
        }
    }

    // Stanford's range scans: a num_cols x num_rows grid of cells holding a
    // vertex or none. Each square of four cells makes two triangles, as
    // MeshLab makes them (vcglib's SparseFaceGrid); a whole square counts as
    // a polygon split in two.
    void triangulateGrid(const Element& e) {
        const int64_t w = header_.gridColumns, h = header_.gridRows;
        if (uint64_t(w) > e.count || uint64_t(h) > e.count || uint64_t(w) * uint64_t(h) != e.count)
            throw invalid("the range_grid has " + std::to_string(e.count) + " cells, but num_cols x num_rows is " +
                          std::to_string(w) + " x " + std::to_string(h));
        const auto at = [&](int64_t row, int64_t column) { return grid_[size_t(row * w + column)]; };
        const auto add = [&](int64_t a, int64_t b, int64_t c) {
            triangles_.push_back(uint32_t(a));
            triangles_.push_back(uint32_t(b));
            triangles_.push_back(uint32_t(c));
        };
        for (int64_t i = 0; i + 1 < h; ++i)
            for (int64_t j = 0; j + 1 < w; ++j) {
                const int64_t v0 = at(i, j), v1 = at(i, j + 1), v2 = at(i + 1, j), v3 = at(i + 1, j + 1);
                const bool first = v0 >= 0 && v2 >= 0 && v3 >= 0, second = v0 >= 0 && v1 >= 0 && v3 >= 0;
                if (first) add(v3, v2, v0);
                if (second) add(v0, v1, v3);
                if (first && second) trianglesFromPolygons_ += 2;
                if (first || second) continue;
                // The other diagonal.
                if (v2 >= 0 && v0 >= 0 && v1 >= 0) add(v2, v0, v1);
                if (v1 >= 0 && v3 >= 0 && v2 >= 0) add(v1, v3, v2);
            }
        grid_.clear();
    }

    // ---- the mesh

    void assemble() {
        drm::Mesh& mesh = out_.mesh;
        mesh.positions = std::move(positions_);
        mesh.triangles = std::move(triangles_);
        mesh.normals = std::move(normals_);
        mesh.colors = std::move(colours_);
        mesh.texCoords = std::move(texCoords_);
        mesh.quality = std::move(quality_);
        mesh.cornerTexCoords = std::move(cornerTexCoords_);
        mesh.faceColors = std::move(faceColours_);
        mesh.faceQuality = std::move(faceQualities_);
        mesh.textures = header_.textures;
        const size_t faces = mesh.faceCount();
        // Texture numbers carry something when one is not 0, or when there
        // are several textures for the corners' coordinates to be in.
        bool anyNonZero = false;
        for (uint32_t number : faceTexture_) anyNonZero = anyNonZero || number != 0;
        const bool severalTextures = mesh.textures.size() > 1 && !mesh.cornerTexCoords.empty();
        if (anyNonZero || (severalTextures && !faceTexture_.empty())) mesh.faceTexture = std::move(faceTexture_);
        else if (severalTextures) mesh.faceTexture.assign(faces, 0);
        out_.trianglesFromPolygons = trianglesFromPolygons_;

        // Tristrips or a range grid beside a face element with attributes:
        // the strips' triangles would have none.
        const auto perFace = [&](size_t size, size_t width, const char* what) {
            if (size != 0 && size != width * faces)
                throw invalid(std::string("the file's ") + what + " cover " + std::to_string(size / width) + " of its " +
                              std::to_string(faces) + " triangles (the others come from tristrips or a range grid)");
        };
        perFace(mesh.cornerTexCoords.size(), 6, "texture coordinates per corner");
        perFace(mesh.faceColors.size(), 4, "face colours");
        perFace(mesh.faceQuality.size(), 1, "face qualities");
        perFace(mesh.faceTexture.size(), 1, "texture numbers");

        std::vector<std::string>& notes = out_.conversions;
        addFloatNote(notes, positionStats_, "vertex position");
        addFloatNote(notes, normalStats_, "vertex normal");
        addFloatNote(notes, texCoordStats_, "vertex texture coordinate");
        addFloatNote(notes, qualityStats_, "vertex quality");
        addFloatNote(notes, cornerTexStats_, "corner texture coordinate");
        addFloatNote(notes, faceQualityStats_, "face quality");
        addColourNote(notes, colourStats_, "vertex");
        addColourNote(notes, faceColourStats_, "face");
        if (texNumbersOutside_ > 0 && !mesh.faceTexture.empty())
            notes.push_back(std::to_string(texNumbersOutside_) + (texNumbersOutside_ == 1 ? " face has" : " faces have") +
                            " a texnumber naming none of the file's " + std::to_string(mesh.textures.size()) +
                            " TextureFile names (face " + std::to_string(firstOutsideFace_) + ": " +
                            std::to_string(firstOutsideNumber_) + (texNumbersOutside_ == 1 ? "): kept as it is" : "): kept as they are"));
    }

    static void addFloatNote(std::vector<std::string>& notes, const FloatStats& stats, const char* what) {
        if (stats.changed == 0) return;
        notes.push_back(std::to_string(stats.changed) + " " + what + (stats.changed == 1 ? " value was" : " values were") +
                        " rounded to the nearest float (the file has " + typeList(stats.sourceTypes) + ")");
    }

    static void addColourNote(std::vector<std::string>& notes, const ColourStats& stats, const char* what) {
        std::vector<std::string> how;
        if (stats.grey) how.push_back("read from its intensity property, as grey");
        const unsigned unit = stats.scaledTypes & (bitOf(Scalar::Float32) | bitOf(Scalar::Float64));
        if (unit) how.push_back("scaled from " + typeList(unit) + " (0..1) to bytes as round(v * 255)");
        if (stats.scaledTypes & bitOf(Scalar::Uint16)) how.push_back("scaled from ushort (0..65535) to bytes as round(v * 255 / 65535)");
        std::vector<std::string> clamped;
        if (stats.clampedUnit > 0) clamped.push_back(std::to_string(stats.clampedUnit) + " outside 0..1");
        if (stats.clampedInteger > 0) clamped.push_back(std::to_string(stats.clampedInteger) + " outside 0..255");
        if (how.empty() && clamped.empty()) return;
        std::string note = std::string("the file's ") + what + " colours were ";
        note += how.empty() ? "clamped to bytes" : joinList(how);
        if (!clamped.empty()) note += "; values clamped: " + joinList(clamped);
        notes.push_back(note);
    }

    static constexpr uint32_t kStripRestart = 0xFFFFFFFFu;

    const Header& header_;
    PlyContents& out_;
    const Element* element_ = nullptr;
    uint64_t vertexCount_ = 0;

    std::vector<float> positions_, normals_, texCoords_, quality_;
    std::vector<uint8_t> colours_;
    std::vector<uint32_t> triangles_;
    std::vector<float> cornerTexCoords_;
    std::vector<uint8_t> faceColours_;
    std::vector<float> faceQualities_;
    std::vector<uint32_t> faceTexture_;
    bool faceHasTexCoords_ = false, faceHasTexNumber_ = false, faceHasColour_ = false, faceHasQuality_ = false;
    size_t trianglesFromPolygons_ = 0;

    // The item being read.
    std::vector<uint32_t> corners_;
    std::vector<float> itemTexCoords_;
    std::vector<uint32_t> strip_;
    int64_t cell_ = -1;
    uint8_t faceColour_[4] = {0, 0, 0, 255};
    float faceQuality_ = 0;
    int64_t texNumber_ = 0;

    std::vector<int64_t> grid_;
    size_t texNumbersOutside_ = 0;
    uint64_t firstOutsideFace_ = 0;
    int64_t firstOutsideNumber_ = 0;

    FloatStats positionStats_, normalStats_, texCoordStats_, qualityStats_, cornerTexStats_, faceQualityStats_;
    ColourStats colourStats_, faceColourStats_;
};

constexpr uint32_t BodyReader::kStripRestart;

}  // namespace

PlyContents readPly(const uint8_t* bytes, size_t size) {
    Header header = parseHeader(bytes, size);
    PlyContents contents;
    assignRoles(header, contents);
    BodyReader(header, contents).read(bytes, size);
    return contents;
}

}  // namespace vcgio
}  // namespace drm
