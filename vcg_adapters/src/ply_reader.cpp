// readPly: see ply_reader.h. The header is parsed into elements whose
// properties each get a role (what of drm::Mesh they fill); the body is
// then read element by element in the file's order. Binary elements of
// scalars alone (vertices, nearly always) are read a property at a time down
// the whole element, one loop per property compiled for its type and byte
// order; faces whose only property is a uchar-counted list of 4-byte
// indices (nearly every mesh file) have a loop of their own; everything
// else, and every ASCII file, is read item by item.
//
// The parts, private to this reader, one file each:
//   ply_header.h/.cpp    the header's model (types, elements, properties,
//                        roles) and its parser
//   ply_roles.cpp        which property fills which part of the mesh
//   ply_values.h         values of the file's types to floats, colour
//                        bytes and whole numbers
//   ply_cursors.h        reading values: binary in either byte order, ASCII
//   ply_body_reader.h    the body reader: element loop and mesh
//                        (ply_body_reader.cpp), binary fast paths
//                        (ply_binary_body.cpp), item by item (ply_items.cpp)
#include "ply_reader.h"

#include "ply_body_reader.h"
#include "ply_header.h"

namespace drm {
namespace vcgio {

PlyContents readPly(const uint8_t* bytes, size_t size) {
    ply::Header header = ply::parseHeader(bytes, size);
    PlyContents contents;
    ply::assignRoles(header, contents);
    ply::BodyReader(header, contents).read(bytes, size);
    return contents;
}

}  // namespace vcgio
}  // namespace drm
