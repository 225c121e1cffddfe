// BodyReader item by item (see ply_body_reader.h): every ASCII file, and
// the binary elements the fast paths (ply_binary_body.cpp) do not take. One
// template over the cursors (ply_cursors.h) reads each item's properties in
// header order, each value's conversion compiled for its type; a list's
// count is checked against the bytes left before its entries are read. Then
// the item's corners, strip or grid cell become triangles.
#include "ply_body_reader.h"

#include <cstdint>

namespace drm {
namespace vcgio {
namespace ply {

template <class Cursor>
void BodyReader::readItems(Cursor& cursor, const Element& e) {
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

template <class Cursor>
[[noreturn]] void BodyReader::refuse(const Cursor& cursor, ReadStatus status, uint64_t item, const Property& p) const {
    if (status == ReadStatus::End) throw endsInside(item);
    throw invalid(where(item) + ": its " + p.name + " " + cursor.problem());
}

template <class T>
void BodyReader::scalar(const Property& p, uint64_t item, T value) {
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
void BodyReader::putFloat(T value, float& out, FloatStats& stats, uint64_t item, const Property& p) {
    if (!toFloat(value, out, stats)) beyondFloat(item, p, value);
}

template <class T>
void BodyReader::entry(const Property& p, uint64_t item, T value) {
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
void BodyReader::emitFace(uint64_t face) {
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
void BodyReader::emitStrips() {
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
void BodyReader::triangulateGrid(const Element& e) {
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

// read() and readBinary() read through all three cursors.
template void BodyReader::readItems<AsciiCursor>(AsciiCursor& cursor, const Element& e);
template void BodyReader::readItems<BinaryCursor<false>>(BinaryCursor<false>& cursor, const Element& e);
template void BodyReader::readItems<BinaryCursor<true>>(BinaryCursor<true>& cursor, const Element& e);

}  // namespace ply
}  // namespace vcgio
}  // namespace drm
