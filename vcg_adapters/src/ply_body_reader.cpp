// BodyReader's element loop (see ply_body_reader.h): each element is
// checked against the bytes left and given room before it is read, by the
// binary fast paths or item by item as its encoding and layout allow; data
// past the last element is named. Then the arrays become the mesh, with
// one note per group of values rounded, scaled or clamped on the way in.
#include "ply_body_reader.h"

#include "drm_vcg/joined_list.h"

#include <algorithm>
#include <utility>

namespace drm {
namespace vcgio {
namespace ply {

BodyReader::BodyReader(const Header& header, PlyContents& out) : header_(header), out_(out) {
    for (const Element& e : header.elements)
        if (e.kind == Kind::Vertex) vertexCount_ = e.count;
}

void BodyReader::read(const uint8_t* bytes, size_t size) {
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

std::string BodyReader::where(uint64_t item) const { return element_->name + " " + std::to_string(item); }
Error BodyReader::endsInside(uint64_t item) const { return invalid("the file ends inside " + where(item) + " (truncated?)"); }

// Checks that the element's items fit in the bytes left, then makes room
// for what they hold.
void BodyReader::begin(const Element& e, size_t bytesLeft) {
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
void BodyReader::noteSourceType(const Property& p) {
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

void BodyReader::finish(const Element& e) {
    if (e.kind == Kind::RangeGrid && hasRole(e, Role::GridCell)) triangulateGrid(e);
}

Error BodyReader::listBeyondEnd(uint64_t item, const Property& p, int64_t entries) const {
    return invalid(where(item) + " has " + std::to_string(entries) + " " + p.name + " entries: the file ends inside it (truncated?)");
}

Error BodyReader::tooFewCorners(uint64_t face, size_t corners) const {
    return invalid(where(face) + " has " + std::to_string(corners) + (corners == 1 ? " corner" : " corners") +
                   " (a face needs at least 3)");
}

void BodyReader::assemble() {
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

void BodyReader::addFloatNote(std::vector<std::string>& notes, const FloatStats& stats, const char* what) {
    if (stats.changed == 0) return;
    notes.push_back(std::to_string(stats.changed) + " " + what + (stats.changed == 1 ? " value was" : " values were") +
                    " rounded to the nearest float (the file has " + typeList(stats.sourceTypes) + ")");
}

void BodyReader::addColourNote(std::vector<std::string>& notes, const ColourStats& stats, const char* what) {
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

}  // namespace ply
}  // namespace vcgio
}  // namespace drm
