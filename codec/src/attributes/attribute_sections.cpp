#include "attributes/attribute_sections.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>

#include "attributes/attribute_coder.h"
#include "container/byte_io.h"
#include "attributes/corner_table.h"
#include "attributes/octahedral.h"
#include "entropy/range_coder.h"
#include "entropy/rank_coder.h"

namespace drm {
namespace {

constexpr uint8_t kMaterialNames = 16, kTextureNames = 17, kMetadata = 18;

// Floats as integers that keep their order (and every bit).
uint32_t orderedBits(float x) {
    uint32_t b;
    std::memcpy(&b, &x, 4);
    return (b & 0x80000000u) ? ~b : (b | 0x80000000u);
}
float fromOrderedBits(uint32_t b) {
    b = (b & 0x80000000u) ? (b & 0x7FFFFFFFu) : ~b;
    float x;
    std::memcpy(&x, &b, 4);
    return x;
}

// One attribute, quantized, per input element.
struct Quantized {
    AttributeValues shape;  // semantic, layout, components, bits, uv grid; values per input element
};

void checkSize(size_t have, size_t per, size_t count, const char* array, const char* unit) {
    if (have != 0 && have != per * count)
        throw Error(ErrorKind::InvalidInput, std::string("the mesh's ") + array + " array holds " + std::to_string(have) + " values; it must hold " +
                    std::to_string(per) + " per " + unit + " (" + std::to_string(per * count) + ")");
}

// A face's material or texture index names an entry of the mesh's list of
// names, where the mesh has one (without names, the indices are kept as
// they are): a writer could not name a material the list lacks.
void checkNameIndices(const std::vector<uint32_t>& indices, const std::vector<std::string>& names, const char* what) {
    if (names.empty()) return;
    for (size_t f = 0; f < indices.size(); ++f)
        if (indices[f] >= names.size())
            throw Error(ErrorKind::InvalidInput, "face " + std::to_string(f) + " uses " + what + " " + std::to_string(indices[f]) +
                        ", but the mesh names only " + std::to_string(names.size()) + " (0.." + std::to_string(names.size() - 1) + ")");
}

std::string cornerName(size_t corner) {
    return "corner " + std::to_string(corner % 3) + " of face " + std::to_string(corner / 3);
}

Quantized colorsOf(const std::vector<uint8_t>& rgba, AttributeLayout layout) {
    Quantized q;
    q.shape.semantic = AttributeSemantic::Color;
    q.shape.layout = layout;
    q.shape.bits = 8;
    bool alpha = false;
    for (size_t i = 3; i < rgba.size(); i += 4) alpha |= rgba[i] != 255;
    q.shape.components = alpha ? 4 : 3;
    q.shape.values.reserve(rgba.size());
    for (size_t i = 0; i < rgba.size(); ++i)
        if (alpha || i % 4 != 3) q.shape.values.push_back(rgba[i]);
    return q;
}

Quantized normalsOf(const std::vector<float>& n, AttributeLayout layout, int bits, bool perCorner) {
    Quantized q;
    q.shape.semantic = AttributeSemantic::Normal;
    q.shape.layout = layout;
    q.shape.bits = bits;
    q.shape.components = 2;
    const size_t count = n.size() / 3;
    q.shape.values.resize(2 * count);
    q.shape.zero.assign(count, 0);
    for (size_t i = 0; i < count; ++i) {
        const double x = n[3 * i], y = n[3 * i + 1], z = n[3 * i + 2];
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
            throw Error(ErrorKind::InvalidInput, (perCorner ? cornerName(i) : "vertex " + std::to_string(i)) + " has a non-finite normal");
        if (x == 0 && y == 0 && z == 0) {
            q.shape.zero[i] = 1;
            continue;
        }
        octahedralEncodeBest(x, y, z, bits, &q.shape.values[2 * i]);
    }
    return q;
}

Quantized texCoordsOf(const std::vector<float>& uv, AttributeLayout layout, int bits, bool perCorner) {
    Quantized q;
    q.shape.semantic = AttributeSemantic::TexCoord;
    q.shape.layout = layout;
    q.shape.bits = bits;
    q.shape.components = 2;
    const size_t count = uv.size() / 2;
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    for (size_t i = 0; i < count; ++i)
        for (int k = 0; k < 2; ++k) {
            const double x = uv[2 * i + k];
            if (!std::isfinite(x))
                throw Error(ErrorKind::InvalidInput, (perCorner ? cornerName(i) : "vertex " + std::to_string(i)) +
                            " has a non-finite texture coordinate");
            if (i == 0 || x < lo[k]) lo[k] = x;
            if (i == 0 || x > hi[k]) hi[k] = x;
        }
    const double top = double((uint32_t(1) << bits) - 1);
    const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    q.shape.uvOrigin[0] = lo[0];
    q.shape.uvOrigin[1] = lo[1];
    q.shape.uvStep = extent > 0 ? extent / top : 1.0;
    q.shape.values.resize(2 * count);
    for (size_t i = 0; i < count; ++i)
        for (int k = 0; k < 2; ++k) {
            const double t = std::floor((double(uv[2 * i + k]) - lo[k]) / q.shape.uvStep + 0.5);
            const uint32_t v = uint32_t(std::min(std::max(t, 0.0), top));
            q.shape.values[2 * i + k] = v;
            if (!std::isfinite(float(lo[k] + double(v) * q.shape.uvStep)))
                throw Error(ErrorKind::InvalidInput, "the texture coordinates span more than a float can hold (" +
                            (perCorner ? cornerName(i) : "vertex " + std::to_string(i)) + ")");
        }
    return q;
}

Quantized floatsOf(const std::vector<float>& x, AttributeSemantic semantic, AttributeLayout layout) {
    Quantized q;
    q.shape.semantic = semantic;
    q.shape.layout = layout;
    q.shape.bits = 32;
    q.shape.components = 1;
    q.shape.values.resize(x.size());
    for (size_t i = 0; i < x.size(); ++i) q.shape.values[i] = orderedBits(x[i]);
    return q;
}

Quantized indicesOf(const std::vector<uint32_t>& x, AttributeSemantic semantic) {
    Quantized q;
    q.shape.semantic = semantic;
    q.shape.layout = AttributeLayout::Face;
    q.shape.bits = 32;
    q.shape.components = 1;
    q.shape.values = x;
    return q;
}

// The values of q in decoded element order: element e of the decoded mesh
// takes input element inputOf[e].
AttributeValues gather(const Quantized& q, const std::vector<uint32_t>& inputOf) {
    AttributeValues a = q.shape;
    const size_t D = size_t(a.components);
    a.values.resize(inputOf.size() * D);
    for (size_t e = 0; e < inputOf.size(); ++e)
        for (size_t j = 0; j < D; ++j) a.values[e * D + j] = q.shape.values[size_t(inputOf[e]) * D + j];
    if (!q.shape.zero.empty()) {
        a.zero.resize(inputOf.size());
        for (size_t e = 0; e < inputOf.size(); ++e) a.zero[e] = q.shape.zero[inputOf[e]];
    }
    return a;
}

const char* sectionName(AttributeSemantic s, AttributeLayout l) {
    const bool face = l == AttributeLayout::Face, corner = l == AttributeLayout::Corner;
    switch (s) {
        case AttributeSemantic::Color: return face ? "face-colors" : "colors";
        case AttributeSemantic::Normal: return corner ? "corner-normals" : "normals";
        case AttributeSemantic::TexCoord: return corner ? "corner-texcoords" : "texcoords";
        case AttributeSemantic::Quality: return face ? "face-quality" : "quality";
        case AttributeSemantic::Material: return "materials";
        case AttributeSemantic::Texture: return "textures";
    }
    return "attribute";
}

// Names and metadata (an .mtl file's text, texture paths) as bytes in an
// order-1 model: one adaptive table per class of the previous byte.
int byteClass(uint8_t b) {
    if (b == ' ' || b == '\t') return 0;
    if (b == '\n' || b == '\r') return 1;
    if (b >= '0' && b <= '9') return 2;
    if (b >= 'a' && b <= 'z') return 3;
    if (b >= 'A' && b <= 'Z') return 4;
    if (b == '.' || b == '_' || b == '/' || b == '\\' || b == '-') return 5;
    return 6;
}
constexpr int kByteClasses = 7;
constexpr uint8_t kTextRaw = 0, kTextCoded = 1;
constexpr size_t kMaxTextRatio = 32;  // decoded text per coded byte, at most (plus kTextSlack)
constexpr size_t kTextSlack = 4096;

std::vector<uint8_t> codeText(const std::string& text) {
    std::vector<AdaptiveFrequencies> tables(kByteClasses, AdaptiveFrequencies(std::vector<uint16_t>(256, 1)));
    RangeEncoder coder;
    int context = 1;
    for (char ch : text) {
        const uint8_t b = uint8_t(ch);
        tables[size_t(context)].encode(coder, b);
        context = byteClass(b);
    }
    return coder.finish();
}

std::string decodeText(const uint8_t* data, size_t size, size_t length) {
    std::vector<AdaptiveFrequencies> tables(kByteClasses, AdaptiveFrequencies(std::vector<uint16_t>(256, 1)));
    RangeDecoder coder(data, size);
    std::string text(length, '\0');
    int context = 1;
    for (size_t i = 0; i < length; ++i) {
        const uint8_t b = uint8_t(tables[size_t(context)].decode(coder));
        text[i] = char(b);
        context = byteClass(b);
    }
    if (coder.bytesPastEnd() > 0) throw Error(ErrorKind::Corrupt, "corrupt file: a name section ends before its last byte");
    return text;
}

std::vector<uint8_t> stringsSection(uint8_t kind, const std::vector<std::string>& strings) {
    ByteWriter out;
    out.u8(kind);
    out.varint(strings.size());
    std::string text;
    for (const std::string& s : strings) {
        out.varint(s.size());
        text += s;
    }
    const std::vector<uint8_t> coded = codeText(text);
    const bool useCoded = coded.size() < text.size() && text.size() <= kMaxTextRatio * coded.size() + kTextSlack;
    out.u8(useCoded ? kTextCoded : kTextRaw);
    if (useCoded) out.bytes(coded);
    else out.bytes(reinterpret_cast<const uint8_t*>(text.data()), text.size());
    return std::move(out.buffer());
}

std::vector<std::string> readStrings(ByteReader& in) {
    const uint64_t count = in.count("string count", in.remaining());
    std::vector<size_t> lengths(count);
    uint64_t total = 0;
    for (size_t& n : lengths) {
        n = size_t(in.count("string length", kMaxTextRatio * in.remaining() + kTextSlack));
        total += n;
    }
    const uint8_t mode = in.u8("text coding");
    if (mode != kTextRaw && mode != kTextCoded) throw Error(ErrorKind::Corrupt, "corrupt file: unknown text coding " + std::to_string(mode));
    const size_t payload = in.remaining();
    if (mode == kTextRaw ? total != payload : total > kMaxTextRatio * payload + kTextSlack)
        throw Error(ErrorKind::Corrupt, "corrupt file: a name section's lengths do not fit its bytes");
    const uint8_t* bytes = in.bytes(payload, "text");
    const std::string text = mode == kTextRaw ? std::string(reinterpret_cast<const char*>(bytes), payload)
                                              : decodeText(bytes, payload, size_t(total));
    std::vector<std::string> strings;
    size_t at = 0;
    for (size_t n : lengths) {
        strings.push_back(text.substr(at, n));
        at += n;
    }
    return strings;
}

// The split of a welded mesh: a vertex for every distinct (vertex, values
// of the welded attributes) among the corners, in corner order, then the
// vertices no face uses. key(c) appends corner c's values.
template <class Key>
void splitVertices(const std::vector<uint32_t>& triangles, size_t vertexCount, Key key, std::vector<uint32_t>& newTriangles,
                   std::vector<uint32_t>& sourceCorner, std::vector<uint32_t>& sourceVertex) {
    std::unordered_map<std::string, uint32_t> index;
    newTriangles.resize(triangles.size());
    std::vector<uint8_t> used(vertexCount, 0);
    std::string k;
    for (size_t c = 0; c < triangles.size(); ++c) {
        k.assign(reinterpret_cast<const char*>(&triangles[c]), 4);
        key(c, k);
        used[triangles[c]] = 1;
        auto found = index.emplace(k, uint32_t(sourceVertex.size()));
        if (found.second) {
            sourceVertex.push_back(triangles[c]);
            sourceCorner.push_back(uint32_t(c));
        }
        newTriangles[c] = found.first->second;
    }
    for (uint32_t v = 0; v < vertexCount; ++v)
        if (!used[v]) {
            sourceVertex.push_back(v);
            sourceCorner.push_back(kNoCorner);
        }
}

void appendValues(std::string& key, const AttributeValues& a, size_t element) {
    const size_t D = size_t(a.components);
    key.append(reinterpret_cast<const char*>(&a.values[element * D]), 4 * D);
    if (!a.zero.empty()) key.push_back(char(a.zero[element]));
}

}  // namespace

void checkAttributes(const Mesh& m, const EncodeOptions& options) {
    const size_t V = m.vertexCount(), F = m.faceCount();
    checkSize(m.colors.size(), 4, V, "colors", "vertex");
    checkSize(m.normals.size(), 3, V, "normals", "vertex");
    checkSize(m.texCoords.size(), 2, V, "texCoords", "vertex");
    checkSize(m.quality.size(), 1, V, "quality", "vertex");
    checkSize(m.cornerTexCoords.size(), 6, F, "cornerTexCoords", "face");
    checkSize(m.cornerNormals.size(), 9, F, "cornerNormals", "face");
    checkSize(m.faceColors.size(), 4, F, "faceColors", "face");
    checkSize(m.faceQuality.size(), 1, F, "faceQuality", "face");
    checkSize(m.faceMaterial.size(), 1, F, "faceMaterial", "face");
    checkSize(m.faceTexture.size(), 1, F, "faceTexture", "face");
    checkNameIndices(m.faceMaterial, m.materials, "material");
    checkNameIndices(m.faceTexture, m.textures, "texture");
    if (options.normalBits < kMinNormalBits || options.normalBits > kMaxNormalBits)
        throw Error(ErrorKind::InvalidInput, "normal bits must be between " + std::to_string(kMinNormalBits) + " and " +
                    std::to_string(kMaxNormalBits) + ", not " + std::to_string(options.normalBits));
    if (options.uvBits < kMinUvBits || options.uvBits > kMaxUvBits)
        throw Error(ErrorKind::InvalidInput, "texture coordinate bits must be between " + std::to_string(kMinUvBits) + " and " +
                    std::to_string(kMaxUvBits) + ", not " + std::to_string(options.uvBits));
    if (options.attributes & ~kAttrAll) throw Error(ErrorKind::InvalidInput, "unknown attribute bits " + std::to_string(options.attributes));
}

bool shouldWeld(const Mesh& mesh, const std::vector<int32_t>& quantized, const EncodeOptions& options) {
    if (options.weld == EncodeOptions::Weld::Off) return false;
    if (options.weld == EncodeOptions::Weld::On) return true;
    const uint32_t perVertex = kAttrColors | kAttrNormals | kAttrTexCoords | kAttrQuality;
    if ((attributesOf(mesh) & options.attributes & perVertex) == 0) return false;
    const Welding w = weld(mesh, quantized);
    return 3 * w.merged() >= mesh.vertexCount();
}

Welding weld(const Mesh& mesh, const std::vector<int32_t>& q) {
    const size_t V = mesh.vertexCount();
    Welding w;
    w.weldedOf.assign(V, kNoVertex);
    std::vector<uint8_t> used(V, 0);
    for (uint32_t v : mesh.triangles)
        if (v < V) used[v] = 1;
    std::unordered_map<uint64_t, uint32_t> byPoint;
    for (uint32_t v = 0; v < V; ++v) {
        if (used[v]) {
            const uint64_t key = (uint64_t(uint32_t(q[3 * v])) << 42) | (uint64_t(uint32_t(q[3 * v + 1])) << 21) |
                                 uint64_t(uint32_t(q[3 * v + 2]));
            auto found = byPoint.emplace(key, uint32_t(w.representative.size()));
            if (found.second) w.representative.push_back(v);
            w.weldedOf[v] = found.first->second;
        } else {
            w.weldedOf[v] = uint32_t(w.representative.size());
            w.representative.push_back(v);
        }
    }
    w.mesh.positions.resize(3 * w.representative.size());
    for (size_t i = 0; i < w.representative.size(); ++i)
        for (int k = 0; k < 3; ++k) w.mesh.positions[3 * i + k] = mesh.positions[3 * size_t(w.representative[i]) + k];
    w.mesh.triangles.resize(mesh.triangles.size());
    for (size_t c = 0; c < mesh.triangles.size(); ++c) w.mesh.triangles[c] = w.weldedOf[mesh.triangles[c]];
    return w;
}

AttributeEncoding encodeAttributeSections(const Mesh& in, const EncodeOptions& options, const DecodedLayout& layout) {
    AttributeEncoding result;
    const uint32_t keep = attributesOf(in) & options.attributes;
    const size_t decodedVertices = layout.grid.size() / 3;
    const size_t corners = layout.triangles.size();
    const CornerTable table = buildCornerTable(layout.triangles, decodedVertices);
    const AttributeMesh mesh{layout.triangles, layout.grid, decodedVertices, table};

    // Where each decoded element comes from in the input.
    std::vector<uint32_t> cornerInput(corners), faceInput = layout.faceInput;
    for (size_t c = 0; c < corners; ++c)
        cornerInput[c] = 3 * layout.faceInput[c / 3] + (uint32_t(c % 3) + layout.faceRotation[c / 3]) % 3;
    std::vector<uint32_t> weldedInput;  // corners' input vertices, then every decoded vertex's representative
    if (layout.welded) {
        weldedInput.resize(corners + decodedVertices);
        for (size_t c = 0; c < corners; ++c) weldedInput[c] = in.triangles[cornerInput[c]];
        for (size_t v = 0; v < decodedVertices; ++v) weldedInput[corners + v] = layout.vertexInput[v];
    }
    const AttributeLayout perVertex = layout.welded ? AttributeLayout::WeldedVertex : AttributeLayout::Vertex;
    const std::vector<uint32_t>& vertexElements = layout.welded ? weldedInput : layout.vertexInput;

    std::vector<AttributeValues> coded;
    if (keep & kAttrColors) coded.push_back(gather(colorsOf(in.colors, perVertex), vertexElements));
    if (keep & kAttrNormals) coded.push_back(gather(normalsOf(in.normals, perVertex, options.normalBits, false), vertexElements));
    if (keep & kAttrTexCoords)
        coded.push_back(gather(texCoordsOf(in.texCoords, perVertex, options.uvBits, false), vertexElements));
    if (keep & kAttrQuality)
        coded.push_back(gather(floatsOf(in.quality, AttributeSemantic::Quality, perVertex), vertexElements));
    if (keep & kAttrCornerTexCoords)
        coded.push_back(gather(texCoordsOf(in.cornerTexCoords, AttributeLayout::Corner, options.uvBits, true), cornerInput));
    if (keep & kAttrCornerNormals)
        coded.push_back(gather(normalsOf(in.cornerNormals, AttributeLayout::Corner, options.normalBits, true), cornerInput));
    if (keep & kAttrFaceColors) coded.push_back(gather(colorsOf(in.faceColors, AttributeLayout::Face), faceInput));
    if (keep & kAttrFaceQuality)
        coded.push_back(gather(floatsOf(in.faceQuality, AttributeSemantic::Quality, AttributeLayout::Face), faceInput));
    if ((keep & kAttrFaceMaterial) && !in.faceMaterial.empty())
        coded.push_back(gather(indicesOf(in.faceMaterial, AttributeSemantic::Material), faceInput));
    if ((keep & kAttrFaceTexture) && !in.faceTexture.empty())
        coded.push_back(gather(indicesOf(in.faceTexture, AttributeSemantic::Texture), faceInput));

    for (const AttributeValues& a : coded) {
        result.sections.push_back(encodeAttribute(a, mesh));
        result.sizes.push_back({sectionName(a.semantic, a.layout), result.sections.back().size()});
    }
    auto addStrings = [&](uint8_t kind, const std::vector<std::string>& strings, const char* name) {
        result.sections.push_back(stringsSection(kind, strings));
        result.sizes.push_back({name, result.sections.back().size()});
    };
    if ((keep & kAttrFaceMaterial) && !in.materials.empty()) addStrings(kMaterialNames, in.materials, "material names");
    if ((keep & kAttrFaceTexture) && !in.textures.empty()) addStrings(kTextureNames, in.textures, "texture names");
    if (keep & kAttrMetadata) {
        std::vector<std::string> pairs;
        for (const auto& kv : in.metadata) {
            pairs.push_back(kv.first);
            pairs.push_back(kv.second);
        }
        addStrings(kMetadata, pairs, "metadata");
    }

    bool anyWelded = false;
    for (const AttributeValues& a : coded) anyWelded |= a.layout == AttributeLayout::WeldedVertex;
    if (layout.welded && !anyWelded) {
        // Welded with no per-vertex attribute to tell corners apart (--weld
        // on): the decoder splits nothing, the welded vertices are the
        // decoded ones.
        result.splitTriangles = layout.triangles;
        result.splitVertexInput = layout.vertexInput;
    } else if (layout.welded) {
        std::vector<uint32_t> sourceCorner;
        splitVertices(
            layout.triangles, decodedVertices,
            [&](size_t c, std::string& key) {
                for (const AttributeValues& a : coded)
                    if (a.layout == AttributeLayout::WeldedVertex) appendValues(key, a, c);
            },
            result.splitTriangles, sourceCorner, result.splitVertexInput);
        for (size_t v = 0; v < result.splitVertexInput.size(); ++v)
            result.splitVertexInput[v] = sourceCorner[v] != kNoCorner ? in.triangles[cornerInput[sourceCorner[v]]]
                                                                       : layout.vertexInput[result.splitVertexInput[v]];
    }
    return result;
}

void decodeAttributeSections(const FileParts& parts, Decoded& result) {
    Mesh& m = result.mesh;
    const size_t V = result.quantized.size() / 3, corners = m.triangles.size();
    // Opposite corners only once a section needs them.
    CornerTable table = buildCornerTable(m.triangles, V, false);
    bool haveOpposites = false;
    const AttributeMesh mesh{m.triangles, result.quantized, V, table};
    std::vector<AttributeValues> welded;
    uint32_t seen = 0;
    for (size_t s = 0; s < parts.attributes.size(); ++s) {
        const FileParts::Payload& p = parts.attributes[s];
        if (p.size == 0) throw Error(ErrorKind::Corrupt, "corrupt file: attribute section " + std::to_string(s) + " is empty");
        const uint8_t kind = p.data[0];
        if (kind >= kMaterialNames) {
            ByteReader in(p.data, p.size, "name section");
            in.u8("kind");
            if (kind == kMaterialNames) m.materials = readStrings(in);
            else if (kind == kTextureNames) m.textures = readStrings(in);
            else if (kind == kMetadata) {
                const std::vector<std::string> pairs = readStrings(in);
                if (pairs.size() % 2) throw Error(ErrorKind::Corrupt, "corrupt file: the metadata section holds an odd number of strings");
                for (size_t i = 0; i < pairs.size(); i += 2) m.metadata.emplace_back(pairs[i], pairs[i + 1]);
            } else {
                throw Error(ErrorKind::Unsupported, "unsupported file: unknown attribute section kind " + std::to_string(kind));
            }
            result.stats.attributeSizes.push_back(
                {kind == kMaterialNames ? "material names" : kind == kTextureNames ? "texture names" : "metadata", p.size});
            continue;
        }
        if (!haveOpposites && attributeNeedsOpposites(p.data, p.size)) {
            addOpposites(table, m.triangles);
            haveOpposites = true;
        }
        AttributeValues a = decodeAttribute(p.data, p.size, mesh);
        const std::string name = sectionName(a.semantic, a.layout);
        result.stats.attributeSizes.push_back({name, p.size});
        const uint32_t bit = 1u << (a.semantic == AttributeSemantic::Color ? (a.layout == AttributeLayout::Face ? 6 : 0)
                                    : a.semantic == AttributeSemantic::Normal ? (a.layout == AttributeLayout::Corner ? 5 : 1)
                                    : a.semantic == AttributeSemantic::TexCoord ? (a.layout == AttributeLayout::Corner ? 4 : 2)
                                    : a.semantic == AttributeSemantic::Quality ? (a.layout == AttributeLayout::Face ? 7 : 3)
                                    : a.semantic == AttributeSemantic::Material ? 8 : 9);
        if (seen & bit) throw Error(ErrorKind::Corrupt, "corrupt file: two " + name + " sections");
        seen |= bit;
        const bool faceSemantic = a.semantic == AttributeSemantic::Material || a.semantic == AttributeSemantic::Texture;
        if ((a.layout == AttributeLayout::Face) != (faceSemantic || bit == kAttrFaceColors || bit == kAttrFaceQuality) ||
            (a.layout == AttributeLayout::Corner && a.semantic != AttributeSemantic::Normal &&
             a.semantic != AttributeSemantic::TexCoord) ||
            (a.semantic == AttributeSemantic::Color && a.bits != 8) ||
            (a.semantic == AttributeSemantic::Normal &&
             (a.components != 2 || a.bits < kMinNormalBits || a.bits > kMaxNormalBits)) ||
            (a.semantic == AttributeSemantic::TexCoord && a.components != 2) ||
            (a.semantic != AttributeSemantic::Color && a.semantic != AttributeSemantic::Normal &&
             a.semantic != AttributeSemantic::TexCoord && (a.components != 1 || a.bits != 32)) ||
            (a.semantic == AttributeSemantic::Color && a.components < 3))
            throw Error(ErrorKind::Corrupt, "corrupt file: the " + name + " section's layout does not fit its kind");
        if (a.layout == AttributeLayout::WeldedVertex) welded.push_back(a);
        // Values to arrays (per element of the layout; welded ones are
        // scattered to vertices after the split below).
        if (a.layout == AttributeLayout::WeldedVertex) continue;
        const size_t n = a.elementCount();
        switch (a.semantic) {
            case AttributeSemantic::Color: {
                std::vector<uint8_t>& out = a.layout == AttributeLayout::Face ? m.faceColors : m.colors;
                out.resize(4 * n);
                for (size_t e = 0; e < n; ++e)
                    for (int k = 0; k < 4; ++k)
                        out[4 * e + k] = k < a.components ? uint8_t(a.values[e * a.components + k]) : 255;
                break;
            }
            case AttributeSemantic::Normal: {
                std::vector<float>& out = a.layout == AttributeLayout::Corner ? m.cornerNormals : m.normals;
                out.assign(3 * n, 0.0f);
                for (size_t e = 0; e < n; ++e) {
                    if (!a.zero.empty() && a.zero[e]) continue;
                    double d[3];
                    octahedralDecode(a.values[2 * e], a.values[2 * e + 1], a.bits, d);
                    for (int k = 0; k < 3; ++k) out[3 * e + k] = float(d[k]);
                }
                break;
            }
            case AttributeSemantic::TexCoord: {
                std::vector<float>& out = a.layout == AttributeLayout::Corner ? m.cornerTexCoords : m.texCoords;
                out.resize(2 * n);
                for (size_t e = 0; e < 2 * n; ++e) {
                    out[e] = float(a.uvOrigin[e % 2] + double(a.values[e]) * a.uvStep);
                    if (!std::isfinite(out[e])) throw Error(ErrorKind::Corrupt, "corrupt file: a texture coordinate is not a finite float");
                }
                break;
            }
            case AttributeSemantic::Quality: {
                std::vector<float>& out = a.layout == AttributeLayout::Face ? m.faceQuality : m.quality;
                out.resize(n);
                for (size_t e = 0; e < n; ++e) out[e] = fromOrderedBits(a.values[e]);
                break;
            }
            case AttributeSemantic::Material: m.faceMaterial = a.values; break;
            case AttributeSemantic::Texture: m.faceTexture = a.values; break;
        }
    }
    if (welded.empty()) return;

    // A welded mesh: one vertex per distinct (vertex, values) again.
    std::vector<uint32_t> triangles, sourceCorner, sourceVertex;
    splitVertices(
        m.triangles, V,
        [&](size_t c, std::string& key) {
            for (const AttributeValues& a : welded) appendValues(key, a, c);
        },
        triangles, sourceCorner, sourceVertex);
    const size_t split = sourceVertex.size();
    std::vector<int32_t> quantized(3 * split);
    for (size_t v = 0; v < split; ++v)
        for (int k = 0; k < 3; ++k) quantized[3 * v + k] = result.quantized[3 * size_t(sourceVertex[v]) + k];
    // The element of a welded attribute that holds split vertex v's values.
    auto elementOf = [&](size_t v) {
        return sourceCorner[v] != kNoCorner ? size_t(sourceCorner[v]) : corners + sourceVertex[v];
    };
    for (const AttributeValues& a : welded) {
        switch (a.semantic) {
            case AttributeSemantic::Color:
                m.colors.resize(4 * split);
                for (size_t v = 0; v < split; ++v)
                    for (int k = 0; k < 4; ++k)
                        m.colors[4 * v + k] = k < a.components ? uint8_t(a.values[elementOf(v) * a.components + k]) : 255;
                break;
            case AttributeSemantic::Normal:
                m.normals.assign(3 * split, 0.0f);
                for (size_t v = 0; v < split; ++v) {
                    const size_t e = elementOf(v);
                    if (!a.zero.empty() && a.zero[e]) continue;
                    double d[3];
                    octahedralDecode(a.values[2 * e], a.values[2 * e + 1], a.bits, d);
                    for (int k = 0; k < 3; ++k) m.normals[3 * v + k] = float(d[k]);
                }
                break;
            case AttributeSemantic::TexCoord:
                m.texCoords.resize(2 * split);
                for (size_t v = 0; v < split; ++v)
                    for (int k = 0; k < 2; ++k) {
                        m.texCoords[2 * v + k] = float(a.uvOrigin[k] + double(a.values[2 * elementOf(v) + k]) * a.uvStep);
                        if (!std::isfinite(m.texCoords[2 * v + k]))
                            throw Error(ErrorKind::Corrupt, "corrupt file: a texture coordinate is not a finite float");
                    }
                break;
            case AttributeSemantic::Quality:
                m.quality.resize(split);
                for (size_t v = 0; v < split; ++v) m.quality[v] = fromOrderedBits(a.values[elementOf(v)]);
                break;
            default: break;
        }
    }
    m.triangles.swap(triangles);
    result.quantized.swap(quantized);
}

std::string attributeSectionName(const uint8_t* data, size_t size) {
    if (size == 0) throw Error(ErrorKind::Corrupt, "corrupt file: an attribute section is empty");
    const uint8_t kind = data[0];
    if (kind == kMaterialNames) return "material names";
    if (kind == kTextureNames) return "texture names";
    if (kind == kMetadata) return "metadata";
    if (kind < uint8_t(AttributeSemantic::Color) || kind > uint8_t(AttributeSemantic::Texture))
        throw Error(ErrorKind::Unsupported, "unsupported file: unknown attribute kind " + std::to_string(kind));
    if (size < 2) throw Error(ErrorKind::Corrupt, "corrupt file: an attribute section ends inside its header");
    return sectionName(AttributeSemantic(kind), AttributeLayout(data[1]));
}

}  // namespace drm
