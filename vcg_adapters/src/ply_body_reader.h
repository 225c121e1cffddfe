// The PLY reader's body reader: reads the elements in the file's order into
// drm::Mesh's arrays, then hands them over with a note on each group of
// values converted on the way in.
// One class, because every path through the body fills the same arrays and
// counts; its members are defined in three files, by what they do:
//   ply_body_reader.cpp  the element loop, per-element checks and set-up, the
//                        mesh and its notes
//   ply_binary_body.cpp  the binary fast paths: a vertex element a property
//                        at a time, faces of uchar-counted 4-byte indices
//   ply_items.cpp        item by item through a cursor (every ASCII file, and
//                        the binary elements the fast paths do not take), and
//                        the triangles faces, strips and grid cells make
// Private to readPly.
#ifndef DRM_VCG_PLY_BODY_READER_H
#define DRM_VCG_PLY_BODY_READER_H

#include "ply_cursors.h"
#include "ply_header.h"
#include "ply_values.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace drm {
namespace vcgio {
namespace ply {

class BodyReader {
public:
    BodyReader(const Header& header, PlyContents& out);

    // Reads every element of the body that starts at header.bodyStart, and
    // fills `out`'s mesh, trianglesFromPolygons and conversions.
    void read(const uint8_t* bytes, size_t size);

private:
    // "face 12", of the element being read.
    std::string where(uint64_t item) const;
    Error endsInside(uint64_t item) const;

    // ---- ply_body_reader.cpp

    void begin(const Element& e, size_t bytesLeft);
    void noteSourceType(const Property& p);
    void finish(const Element& e);
    void assemble();
    static void addFloatNote(std::vector<std::string>& notes, const FloatStats& stats, const char* what);
    static void addColourNote(std::vector<std::string>& notes, const ColourStats& stats, const char* what);

    static bool hasRole(const Element& e, Role role) {
        for (const Property& p : e.properties)
            if (p.role == role) return true;
        return false;
    }

    template <class T>
    [[noreturn]] void beyondFloat(uint64_t item, const Property& p, T value) const {
        throw invalid(where(item) + ": its " + p.name + " " + show(value) + " is beyond the range of float");
    }
    template <class T>
    [[noreturn]] void badCorner(uint64_t face, T index) const {
        throw invalid(where(face) + " refers to vertex " + show(index) + ", but the file has " + std::to_string(vertexCount_) +
                      " vertices");
    }
    Error listBeyondEnd(uint64_t item, const Property& p, int64_t entries) const;
    Error tooFewCorners(uint64_t face, size_t corners) const;

    // ---- ply_binary_body.cpp

    template <bool BigEndian>
    const uint8_t* readBinary(const uint8_t* at, const uint8_t* end, const Element& e);
    template <bool BigEndian>
    void readColumns(const uint8_t* base, size_t stride, const Element& e);
    template <class T, bool BigEndian>
    void column(const uint8_t* at, size_t stride, size_t count, const Property& p);
    template <class T, bool BigEndian>
    void floatColumn(const uint8_t* at, size_t stride, size_t count, const Property& p, float* out, size_t outStride,
                     FloatStats& stats);
    template <class Index, bool BigEndian>
    const uint8_t* readCornerLists(const uint8_t* at, const uint8_t* end, const Element& e);
    template <class Index>
    uint32_t checkedCorner(uint64_t face, Index index) const;

    // ---- ply_items.cpp

    template <class Cursor>
    void readItems(Cursor& cursor, const Element& e);
    template <class Cursor>
    [[noreturn]] void refuse(const Cursor& cursor, ReadStatus status, uint64_t item, const Property& p) const;
    template <class T>
    void scalar(const Property& p, uint64_t item, T value);
    template <class T>
    void putFloat(T value, float& out, FloatStats& stats, uint64_t item, const Property& p);
    template <class T>
    void entry(const Property& p, uint64_t item, T value);
    void emitFace(uint64_t face);
    void emitStrips();
    void triangulateGrid(const Element& e);

    // ---- state

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

}  // namespace ply
}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_PLY_BODY_READER_H
