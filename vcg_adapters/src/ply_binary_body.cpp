// BodyReader's binary fast paths (see ply_body_reader.h), for the layouts
// nearly every binary mesh file has. A vertex element of scalars alone is
// read a property at a time down the whole element, one loop per property
// compiled for its type and byte order; faces whose only property is a
// uchar-counted list of 4-byte indices have a loop of their own. Any other
// binary element goes item by item (ply_items.cpp).
#include "ply_body_reader.h"

#include <algorithm>

namespace drm {
namespace vcgio {
namespace ply {

template <bool BigEndian>
const uint8_t* BodyReader::readBinary(const uint8_t* at, const uint8_t* end, const Element& e) {
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
void BodyReader::readColumns(const uint8_t* base, size_t stride, const Element& e) {
    size_t offset = 0;
    for (const Property& p : e.properties) {
        withType(p.type, [&](auto tag) { this->column<decltype(tag), BigEndian>(base + offset, stride, size_t(e.count), p); });
        offset += describe(p.type).size;
    }
}

template <class T, bool BigEndian>
void BodyReader::column(const uint8_t* at, size_t stride, size_t count, const Property& p) {
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
void BodyReader::floatColumn(const uint8_t* at, size_t stride, size_t count, const Property& p, float* out,
                             size_t outStride, FloatStats& stats) {
    for (size_t i = 0; i < count; ++i, at += stride, out += outStride)
        if (!toFloat(load<T, BigEndian>(at), *out, stats)) beyondFloat(i, p, load<T, BigEndian>(at));
}

// Faces of a uchar-counted list of 4-byte indices and nothing else.
template <class Index, bool BigEndian>
const uint8_t* BodyReader::readCornerLists(const uint8_t* at, const uint8_t* end, const Element& e) {
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
uint32_t BodyReader::checkedCorner(uint64_t face, Index index) const {
    if (int64_t(index) < 0 || uint64_t(index) >= vertexCount_) badCorner(face, index);
    return uint32_t(index);
}

// read() takes both byte orders.
template const uint8_t* BodyReader::readBinary<false>(const uint8_t* at, const uint8_t* end, const Element& e);
template const uint8_t* BodyReader::readBinary<true>(const uint8_t* at, const uint8_t* end, const Element& e);

}  // namespace ply
}  // namespace vcgio
}  // namespace drm
