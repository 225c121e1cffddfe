// The PLY reader's model of a file's header: the scalar types, the elements
// and their properties, and the role each property is given (what of
// drm::Mesh it fills). parseHeader (ply_header.cpp) builds it from the
// header's text, assignRoles (ply_roles.cpp) gives the roles, and the body
// reader (ply_body_reader.h) reads the body by it. Private to readPly.
#ifndef DRM_VCG_PLY_HEADER_H
#define DRM_VCG_PLY_HEADER_H

#include "ply_reader.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace drm {
namespace vcgio {
namespace ply {

inline Error invalid(const std::string& message) { return Error(ErrorKind::InvalidInput, message); }

// PLY's blanks: space, tab, CR, LF, vertical tab, form feed.
inline bool isBlank(uint8_t c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// ---------------------------------------------------------------- types

enum class Scalar : uint8_t { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

struct ScalarName {
    const char* name;
    const char* alias;
    size_t size;
    bool integer;
};

inline constexpr ScalarName kScalars[] = {
    {"char", "int8", 1, true},      {"uchar", "uint8", 1, true},  {"short", "int16", 2, true},
    {"ushort", "uint16", 2, true},  {"int", "int32", 4, true},    {"uint", "uint32", 4, true},
    {"float", "float32", 4, false}, {"double", "float64", 8, false},
};

inline const ScalarName& describe(Scalar type) { return kScalars[size_t(type)]; }
inline unsigned bitOf(Scalar type) { return 1u << unsigned(type); }

// False if `text` names no scalar type (by its name or its alias).
bool scalarNamed(const std::string& text, Scalar& type);

// "double", "int and double": the types whose bits are set.
std::string typeList(unsigned types);

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

// The header of the file `bytes` holds, every property with Role::Other.
// Throws drm::Error naming the header line at fault.
Header parseHeader(const uint8_t* bytes, size_t size);

// What each property becomes; what is not kept goes into `out`'s lists.
void assignRoles(Header& header, PlyContents& out);

}  // namespace ply
}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_PLY_HEADER_H
