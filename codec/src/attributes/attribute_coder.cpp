#include "attributes/attribute_coder.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "entropy/bit_model.h"
#include "common.h"
#include "container/byte_io.h"
#include "drmcodec/drmcodec.h"
#include "attributes/octahedral.h"
#include "entropy/range_coder.h"

namespace drm {
namespace {

constexpr int kMaxComponents = 4;
constexpr int kMaxValueBits = 32;
constexpr int kMaxLength = kMaxValueBits + 1;
constexpr int kMagnitudeContexts = 6;
constexpr uint8_t kFlagZeroNormals = 1;

// The residual models of one component: contexts from the previous
// residual's size on this component and, for the later components,
// whether the first component's residual was zero.
struct ComponentModels {
    BitModel zero[2 * kMagnitudeContexts];
    BitModel longer[2 * kMagnitudeContexts][kMaxLength];
    BitModel sign[2];
    BitModel low[kMaxLength + 1][2];
};

struct ResidualCoder {
    explicit ResidualCoder(int components, int bits) : models(size_t(components)), magnitude(size_t(components), 0), bits(bits) {}
    std::vector<ComponentModels> models;
    std::vector<uint64_t> magnitude;  // of the previous residual, per component
    int bits;

    // Codes value v (encoder) or decodes it (decoder) as a residual from
    // prediction p, modulo 2^bits.
    template <class Io>
    void code(Io& io, const uint32_t* prediction, uint32_t* value) {
        const uint64_t modulus = uint64_t(1) << bits, half = modulus >> 1;
        bool firstZero = false;
        for (size_t j = 0; j < models.size(); ++j) {
            ComponentModels& m = models[j];
            int64_t r = 0;
            if (Io::kEncoding) {
                uint64_t d = (uint64_t(value[j]) - uint64_t(prediction[j])) & (modulus - 1);
                r = d >= half && half > 0 ? int64_t(d) - int64_t(modulus) : int64_t(d);
            }
            const int context = std::min(bitLength(magnitude[j]), kMagnitudeContexts - 1) +
                                (j > 0 && firstZero ? kMagnitudeContexts : 0);
            const uint64_t mag = r < 0 ? uint64_t(-r) : uint64_t(r);
            uint64_t decodedMag = 0;
            if (!io.bit(m.zero[context], mag == 0)) {
                const int n0 = bitLength(mag);
                int n = 1;
                while (n < kMaxLength && io.bit(m.longer[context][n], n0 > n)) ++n;
                if (n > bits) throw Error(ErrorKind::Corrupt, "corrupt file: an attribute residual is longer than its values");
                const int negative = io.bit(m.sign[j > 0 ? 1 : 0], r < 0);
                uint64_t low = 0;
                const int modelled = std::min(n - 1, 2);
                for (int i = 0; i < modelled; ++i) {
                    const int shift = n - 2 - i;
                    low = (low << 1) | uint64_t(io.bit(m.low[n][i], int((mag >> shift) & 1)));
                }
                const int rest = n - 1 - modelled;
                if (rest > 0) low = (low << rest) | io.wide(mag & ((uint64_t(1) << rest) - 1), rest);
                decodedMag = (uint64_t(1) << (n - 1)) | low;
                r = negative ? -int64_t(decodedMag) : int64_t(decodedMag);
            } else {
                r = 0;
            }
            if (j == 0) firstZero = decodedMag == 0;
            magnitude[j] = decodedMag;
            if (!Io::kEncoding) value[j] = uint32_t((uint64_t(prediction[j]) + uint64_t(r)) & (modulus - 1));
        }
    }
};

bool usesWedges(AttributeLayout layout) { return layout == AttributeLayout::Corner || layout == AttributeLayout::WeldedVertex; }
bool hasVertexValues(AttributeLayout layout) {
    return layout == AttributeLayout::Vertex || layout == AttributeLayout::WeldedVertex;
}

std::vector<AttributePredictor> predictorsFor(const AttributeValues& a) {
    if (a.layout == AttributeLayout::Face) return {AttributePredictor::AdjacentFace, AttributePredictor::Previous};
    std::vector<AttributePredictor> p = {AttributePredictor::Parallelogram, AttributePredictor::RingAverage,
                                         AttributePredictor::Previous};
    if (a.semantic == AttributeSemantic::Normal) {
        p.insert(p.begin(), AttributePredictor::GeometricNormal);
        if (a.layout != AttributeLayout::Vertex) p.push_back(AttributePredictor::FaceOrGeometricNormal);
    }
    if (a.semantic == AttributeSemantic::TexCoord) {
        p.insert(p.begin(), AttributePredictor::GeometricUv);
    }
    return p;
}

// Everything both coders keep while walking the wedges of one attribute.
struct WedgeWalk {
    const AttributeMesh& mesh;
    const AttributeValues& shape;  // semantic, layout, components, bits
    AttributePredictor predictor;
    std::vector<uint32_t> wedgeOf;       // per corner
    uint32_t cornerWedges = 0;           // wedges with corners; then one per isolated vertex
    std::vector<uint32_t> wedgeStart, wedgeCorners;  // corners of each wedge (CSR)
    std::vector<uint32_t> isolated;      // vertices without corners (per-vertex layouts)
    std::vector<uint32_t> values;        // per wedge, components each
    std::vector<uint8_t> zero;           // per wedge (normals with zero flags)
    int64_t orientation = 0;             // GeometricUv: texture triangles turned + minus -

    WedgeWalk(const AttributeMesh& m, const AttributeValues& s, AttributePredictor p) : mesh(m), shape(s), predictor(p) {}

    size_t D() const { return size_t(shape.components); }
    uint32_t top() const { return uint32_t((uint64_t(1) << shape.bits) - 1); }

    void buildCorners() {
        const size_t wedges = cornerWedges;
        wedgeStart.assign(wedges + 1, 0);
        for (uint32_t w : wedgeOf) ++wedgeStart[size_t(w) + 1];
        for (size_t w = 0; w < wedges; ++w) wedgeStart[w + 1] += wedgeStart[w];
        wedgeCorners.resize(wedgeOf.size());
        std::vector<uint32_t> fill(wedgeStart.begin(), wedgeStart.end() - 1);
        for (uint32_t c = 0; c < wedgeOf.size(); ++c) wedgeCorners[fill[wedgeOf[c]]++] = c;
        if (hasVertexValues(shape.layout))
            for (uint32_t v = 0; v < mesh.vertexCount; ++v)
                if (mesh.corners.cornerStart[v] == mesh.corners.cornerStart[v + 1]) isolated.push_back(v);
    }

    void previous(uint32_t w, uint32_t* p) const {
        for (size_t j = 0; j < D(); ++j) p[j] = w > 0 ? values[(w - 1) * D() + j] : 0;
    }

    bool ringAverage(uint32_t w, uint32_t* p) const {
        uint64_t sum[kMaxComponents] = {0, 0, 0, 0};
        uint64_t count = 0;
        for (uint32_t i = wedgeStart[w]; i < wedgeStart[w + 1]; ++i) {
            const uint32_t c = wedgeCorners[i];
            for (uint32_t n : {nextCorner(c), previousCorner(c)}) {
                const uint32_t x = wedgeOf[n];
                if (x >= w) continue;
                for (size_t j = 0; j < D(); ++j) sum[j] += values[x * D() + j];
                ++count;
            }
        }
        if (count == 0) return false;
        for (size_t j = 0; j < D(); ++j) p[j] = uint32_t((sum[j] + count / 2) / count);
        return true;
    }

    bool parallelogram(uint32_t w, uint32_t* p) const {
        int64_t sum[kMaxComponents] = {0, 0, 0, 0};
        int64_t count = 0;
        const int64_t hi = top();
        for (uint32_t i = wedgeStart[w]; i < wedgeStart[w + 1]; ++i) {
            const uint32_t c = wedgeCorners[i], o = mesh.corners.opposite[c];
            if (o == kNoCorner) continue;
            const uint32_t a = wedgeOf[nextCorner(c)], b = wedgeOf[previousCorner(c)], x = wedgeOf[o];
            if (a >= w || b >= w || x >= w) continue;
            for (size_t j = 0; j < D(); ++j) {
                const int64_t v = int64_t(values[a * D() + j]) + int64_t(values[b * D() + j]) - int64_t(values[x * D() + j]);
                sum[j] += std::min(std::max(v, int64_t(0)), hi);
            }
            ++count;
        }
        if (count == 0) return false;
        for (size_t j = 0; j < D(); ++j) p[j] = uint32_t((sum[j] + count / 2) / count);
        return true;
    }

    // The value of a decoded corner in the face of the wedge's first corner.
    bool sameFace(uint32_t w, uint32_t* p) const {
        const uint32_t c = wedgeCorners[wedgeStart[w]];
        for (uint32_t n : {previousCorner(c), nextCorner(c)}) {
            const uint32_t x = wedgeOf[n];
            if (x >= w) continue;
            for (size_t j = 0; j < D(); ++j) p[j] = values[x * D() + j];
            return true;
        }
        return false;
    }

    double coordinate(uint32_t corner, int k) const {
        return double(mesh.grid[3 * size_t(mesh.triangles[corner]) + size_t(k)]);
    }

    bool geometricNormal(uint32_t w, uint32_t* p) const {
        double n[3] = {0, 0, 0};
        for (uint32_t i = wedgeStart[w]; i < wedgeStart[w + 1]; ++i) {
            const uint32_t c = wedgeCorners[i], a = nextCorner(c), b = previousCorner(c);
            double e1[3], e2[3];
            for (int k = 0; k < 3; ++k) {
                e1[k] = coordinate(a, k) - coordinate(c, k);
                e2[k] = coordinate(b, k) - coordinate(c, k);
            }
            n[0] += e1[1] * e2[2] - e1[2] * e2[1];
            n[1] += e1[2] * e2[0] - e1[0] * e2[2];
            n[2] += e1[0] * e2[1] - e1[1] * e2[0];
        }
        if (n[0] == 0 && n[1] == 0 && n[2] == 0) return false;
        octahedralEncode(n[0], n[1], n[2], shape.bits, p);
        return true;
    }

    // p: the prediction on the side the orientation count expects; other
    // (if not null): the one mirrored across A-B, and *sided whether the
    // two differ (the coder then says which holds, per wedge).
    bool geometricUv(uint32_t w, uint32_t* p, uint32_t* other = nullptr, bool* sided = nullptr) const {
        // The mean over every corner of the wedge whose two neighbours in
        // its face are decoded (each one triangle's shape carried into
        // texture space), on the side the orientation count expects; other:
        // the mean mirrored across each edge.
        double sum[2] = {0, 0}, mirroredSum[2] = {0, 0};
        int count = 0;
        for (uint32_t i = wedgeStart[w]; i < wedgeStart[w + 1]; ++i) {
            const uint32_t c = wedgeCorners[i], a = nextCorner(c), b = previousCorner(c);
            const uint32_t wa = wedgeOf[a], wb = wedgeOf[b];
            if (wa >= w || wb >= w) continue;
            double e[3], f[3], ee = 0, fe = 0;
            for (int k = 0; k < 3; ++k) {
                e[k] = coordinate(b, k) - coordinate(a, k);
                f[k] = coordinate(c, k) - coordinate(a, k);
                ee += e[k] * e[k];
                fe += f[k] * e[k];
            }
            const double ua = values[wa * 2], va = values[wa * 2 + 1];
            ++count;
            if (ee == 0) {
                sum[0] += ua;
                sum[1] += va;
                mirroredSum[0] += ua;
                mirroredSum[1] += va;
                continue;
            }
            const double s = fe / ee;
            double h = 0;
            for (int k = 0; k < 3; ++k) {
                const double q = f[k] - s * e[k];
                h += q * q;
            }
            const double t = std::sqrt(h / ee);
            const double du = double(values[wb * 2]) - ua, dv = double(values[wb * 2 + 1]) - va;
            const double sign = orientation >= 0 ? 1.0 : -1.0;
            sum[0] += ua + s * du - sign * t * dv;
            sum[1] += va + s * dv + sign * t * du;
            mirroredSum[0] += ua + s * du + sign * t * dv;
            mirroredSum[1] += va + s * dv - sign * t * du;
        }
        if (count == 0) return false;
        const double hi = double(top());
        for (int k = 0; k < 2; ++k) p[k] = uint32_t(std::min(std::max(std::floor(sum[k] / count + 0.5), 0.0), hi));
        if (other) {
            for (int k = 0; k < 2; ++k)
                other[k] = uint32_t(std::min(std::max(std::floor(mirroredSum[k] / count + 0.5), 0.0), hi));
            *sided = other[0] != p[0] || other[1] != p[1];
        }
        return true;
    }

    // After wedge w's value is known: which way its texture triangle turns.
    void learnOrientation(uint32_t w) {
        for (uint32_t i = wedgeStart[w]; i < wedgeStart[w + 1]; ++i) {
            const uint32_t c = wedgeCorners[i];
            const uint32_t wa = wedgeOf[nextCorner(c)], wb = wedgeOf[previousCorner(c)];
            if (wa >= w || wb >= w) continue;
            const int64_t ax = int64_t(values[wa * 2]), ay = int64_t(values[wa * 2 + 1]);
            const int64_t bx = int64_t(values[wb * 2]) - ax, by = int64_t(values[wb * 2 + 1]) - ay;
            const int64_t cx = int64_t(values[w * 2]) - ax, cy = int64_t(values[w * 2 + 1]) - ay;
            const int64_t cross = bx * cy - by * cx;
            orientation += cross > 0 ? 1 : (cross < 0 ? -1 : 0);
            return;
        }
    }

    void predict(uint32_t w, uint32_t* p) const {
        if (w >= cornerWedges) return previous(w, p);  // an isolated vertex
        bool made = false;
        switch (predictor) {
            case AttributePredictor::GeometricNormal: made = geometricNormal(w, p); break;
            case AttributePredictor::FaceOrGeometricNormal: made = sameFace(w, p) || geometricNormal(w, p); break;
            case AttributePredictor::GeometricUv: made = geometricUv(w, p); break;
            case AttributePredictor::Parallelogram: made = parallelogram(w, p); break;
            case AttributePredictor::RingAverage: made = ringAverage(w, p); break;
            default: break;
        }
        if (!made && predictor != AttributePredictor::Previous && predictor != AttributePredictor::GeometricNormal &&
            predictor != AttributePredictor::FaceOrGeometricNormal)
            made = ringAverage(w, p);
        if (!made) previous(w, p);
    }
};

// Faces: the value of the first earlier face across an edge, else the
// previous face's.
void predictFace(const AttributeMesh& mesh, AttributePredictor predictor, const std::vector<uint32_t>& values, size_t D,
                 uint32_t f, uint32_t* p) {
    if (predictor == AttributePredictor::AdjacentFace)
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t o = mesh.corners.opposite[3 * size_t(f) + k];
            if (o != kNoCorner && o / 3 < f) {
                for (size_t j = 0; j < D; ++j) p[j] = values[size_t(o / 3) * D + j];
                return;
            }
        }
    for (size_t j = 0; j < D; ++j) p[j] = f > 0 ? values[size_t(f - 1) * D + j] : 0;
}

// The seams of a corner layout: per interior edge, whether the values at
// either end differ between its two faces.
std::vector<uint8_t> seamsOf(const AttributeValues& a, const AttributeMesh& mesh) {
    const size_t D = size_t(a.components);
    auto same = [&](uint32_t x, uint32_t y) {
        if (!a.zero.empty() && a.zero[x] != a.zero[y]) return false;
        for (size_t j = 0; j < D; ++j)
            if (a.values[x * D + j] != a.values[y * D + j]) return false;
        return true;
    };
    std::vector<uint8_t> seam(mesh.corners.interiorEdges.size());
    for (size_t e = 0; e < seam.size(); ++e) {
        const uint32_t c0 = mesh.corners.interiorEdges[e], c1 = mesh.corners.opposite[c0];
        const uint32_t a0 = nextCorner(c0), b0 = previousCorner(c0);
        const uint32_t a1 = cornerAt(mesh.triangles, c1 / 3, mesh.triangles[a0]);
        const uint32_t b1 = cornerAt(mesh.triangles, c1 / 3, mesh.triangles[b0]);
        seam[e] = !(same(a0, a1) && same(b0, b1));
    }
    return seam;
}

template <class Io>
void codeSeams(Io& io, std::vector<uint8_t>& seam) {
    BitModel models[2];
    int previous = 0;
    for (uint8_t& s : seam) {
        s = uint8_t(io.bit(models[previous], s));
        previous = s;
    }
}

// Codes (encoder) or decodes the seam bits of corner layouts, then builds
// the wedges and sizes their value arrays (all zero).
template <class Io>
void codeWedgeLayout(Io& io, WedgeWalk& walk, std::vector<uint8_t>& seam) {
    const bool wedged = usesWedges(walk.shape.layout);
    if (wedged) codeSeams(io, seam);
    walk.wedgeOf = wedgesOf(walk.mesh, seam, !wedged, &walk.cornerWedges);
    walk.buildCorners();
    const uint32_t wedges = walk.cornerWedges + uint32_t(walk.isolated.size());
    walk.values.assign(size_t(wedges) * walk.D(), 0);
    walk.zero.assign(wedges, 0);
}

// Codes (encoder) or decodes the values of the wedges, in order.
template <class Io>
void codeWedges(Io& io, WedgeWalk& walk, bool zeroFlags) {
    ResidualCoder residuals(walk.shape.components, walk.shape.bits);
    BitModel zeroModel[2], sideModel[2];
    int previousZero = 0, previousFlip = 0;
    const size_t D = walk.D();
    const uint32_t wedges = walk.cornerWedges + uint32_t(walk.isolated.size());
    uint32_t p[kMaxComponents];
    for (uint32_t w = 0; w < wedges; ++w) {
        if (zeroFlags) {
            walk.zero[w] = uint8_t(io.bit(zeroModel[previousZero], walk.zero[w]));
            previousZero = walk.zero[w];
            if (walk.zero[w]) {
                for (size_t j = 0; j < D; ++j) walk.values[w * D + j] = 0;
                continue;
            }
        }
        bool sided = false;
        uint32_t mirrored[kMaxComponents];
        if (walk.predictor == AttributePredictor::GeometricUv && w < walk.cornerWedges &&
            walk.geometricUv(w, p, mirrored, &sided)) {
            if (sided) {
                // Which side of the edge the texture triangle lies on: UV
                // islands may be mirrored, so the coder says it per wedge
                // (cheap while the orientation count is right).
                int flip = 0;
                if (Io::kEncoding) {
                    const uint32_t* v = &walk.values[w * D];
                    auto distance = [&](const uint32_t* q) {
                        return std::llabs(int64_t(v[0]) - int64_t(q[0])) + std::llabs(int64_t(v[1]) - int64_t(q[1]));
                    };
                    flip = distance(mirrored) < distance(p) ? 1 : 0;
                }
                flip = io.bit(sideModel[previousFlip], flip);
                previousFlip = flip;
                if (flip) std::copy(mirrored, mirrored + 2, p);
            }
        } else {
            walk.predict(w, p);
        }
        residuals.code(io, p, &walk.values[w * D]);
        if (walk.predictor == AttributePredictor::GeometricUv && w < walk.cornerWedges) walk.learnOrientation(w);
    }
}

std::vector<uint8_t> encodeWith(const AttributeValues& a, const AttributeMesh& mesh, AttributePredictor predictor) {
    ByteWriter out;
    const bool zeroFlags = !a.zero.empty() && std::find(a.zero.begin(), a.zero.end(), 1) != a.zero.end();
    out.u8(uint8_t(a.semantic));
    out.u8(uint8_t(a.layout));
    out.u8(uint8_t(predictor));
    out.u8(uint8_t(a.components));
    out.u8(uint8_t(a.bits));
    out.u8(zeroFlags ? kFlagZeroNormals : 0);
    if (a.semantic == AttributeSemantic::TexCoord) {
        out.f64(a.uvOrigin[0]);
        out.f64(a.uvOrigin[1]);
        out.f64(a.uvStep);
    }
    RangeEncoder coder;
    Writer io{coder};
    const size_t D = size_t(a.components);
    if (a.layout == AttributeLayout::Face) {
        ResidualCoder residuals(a.components, a.bits);
        std::vector<uint32_t> values = a.values;
        uint32_t p[kMaxComponents];
        for (uint32_t f = 0; f < a.elementCount(); ++f) {
            predictFace(mesh, predictor, values, D, f, p);
            residuals.code(io, p, &values[size_t(f) * D]);
        }
    } else {
        WedgeWalk walk(mesh, a, predictor);
        std::vector<uint8_t> seam;
        if (usesWedges(a.layout)) seam = seamsOf(a, mesh);
        codeWedgeLayout(io, walk, seam);
        // A wedge's value is that of any of its corners (they agree: no seam
        // joins them), or of its vertex in per-vertex layouts.
        const size_t cornerBase = a.layout == AttributeLayout::WeldedVertex ? mesh.triangles.size() : 0;
        std::vector<uint8_t> set(walk.cornerWedges, 0);
        for (uint32_t c = 0; c < walk.wedgeOf.size(); ++c) {
            const uint32_t w = walk.wedgeOf[c];
            if (set[w]) continue;
            set[w] = 1;
            const size_t element = a.layout == AttributeLayout::Vertex ? size_t(mesh.triangles[c]) : size_t(c);
            for (size_t j = 0; j < D; ++j) walk.values[w * D + j] = a.values[element * D + j];
            if (zeroFlags) walk.zero[w] = a.zero[element];
        }
        for (size_t i = 0; i < walk.isolated.size(); ++i) {
            const size_t element = cornerBase + walk.isolated[i];
            const size_t w = walk.cornerWedges + i;
            for (size_t j = 0; j < D; ++j) walk.values[w * D + j] = a.values[element * D + j];
            if (zeroFlags) walk.zero[w] = a.zero[element];
        }
        codeWedges(io, walk, zeroFlags);
    }
    out.bytes(coder.finish());
    return std::move(out.buffer());
}

}  // namespace

std::vector<uint32_t> wedgesOf(const AttributeMesh& mesh, const std::vector<uint8_t>& seam, bool perVertex,
                               uint32_t* wedgeCount) {
    const size_t corners = mesh.triangles.size();
    std::vector<uint32_t> wedgeOf(corners);
    const uint32_t kNoWedge = kNoIndex;
    uint32_t next = 0;
    if (perVertex) {
        std::vector<uint32_t> ofVertex(mesh.vertexCount, kNoWedge);
        for (size_t c = 0; c < corners; ++c) {
            uint32_t& w = ofVertex[mesh.triangles[c]];
            if (w == kNoWedge) w = next++;
            wedgeOf[c] = w;
        }
    } else {
        UnionFind sets(corners);
        for (size_t e = 0; e < seam.size(); ++e) {
            if (seam[e]) continue;
            const uint32_t c0 = mesh.corners.interiorEdges[e], c1 = mesh.corners.opposite[c0];
            const uint32_t a0 = nextCorner(c0), b0 = previousCorner(c0);
            sets.joinToLower(a0, cornerAt(mesh.triangles, c1 / 3, mesh.triangles[a0]));
            sets.joinToLower(b0, cornerAt(mesh.triangles, c1 / 3, mesh.triangles[b0]));
        }
        std::vector<uint32_t> ofRoot(corners, kNoWedge);
        for (size_t c = 0; c < corners; ++c) {
            uint32_t& w = ofRoot[sets.root(uint32_t(c))];
            if (w == kNoWedge) w = next++;
            wedgeOf[c] = w;
        }
    }
    *wedgeCount = next;
    return wedgeOf;
}

std::vector<uint8_t> encodeAttribute(const AttributeValues& a, const AttributeMesh& mesh) {
    std::vector<uint8_t> best;
    for (AttributePredictor p : predictorsFor(a)) {
        std::vector<uint8_t> bytes = encodeWith(a, mesh, p);
        if (best.empty() || bytes.size() < best.size()) best.swap(bytes);
    }
    return best;
}

bool attributeNeedsOpposites(const uint8_t* data, size_t size) {
    if (size < 3) return false;
    const AttributeLayout layout = AttributeLayout(data[1]);
    const AttributePredictor predictor = AttributePredictor(data[2]);
    return usesWedges(layout) || predictor == AttributePredictor::Parallelogram ||
           predictor == AttributePredictor::AdjacentFace;
}

AttributeValues decodeAttribute(const uint8_t* data, size_t size, const AttributeMesh& mesh) {
    ByteReader in(data, size, "attribute section");
    AttributeValues a;
    const uint8_t semantic = in.u8("attribute kind");
    if (semantic < uint8_t(AttributeSemantic::Color) || semantic > uint8_t(AttributeSemantic::Texture))
        throw Error(ErrorKind::Unsupported, "unsupported file: unknown attribute kind " + std::to_string(semantic));
    a.semantic = AttributeSemantic(semantic);
    const uint8_t layout = in.u8("attribute layout");
    if (layout > uint8_t(AttributeLayout::WeldedVertex))
        throw Error(ErrorKind::Corrupt, "corrupt file: unknown attribute layout " + std::to_string(layout));
    a.layout = AttributeLayout(layout);
    const uint8_t predictor = in.u8("attribute predictor");
    a.components = in.u8("attribute components");
    a.bits = in.u8("attribute bits");
    const uint8_t flags = in.u8("attribute flags");
    if (a.components < 1 || a.components > kMaxComponents || a.bits < 1 || a.bits > kMaxValueBits ||
        (flags & ~kFlagZeroNormals) != 0)
        throw Error(ErrorKind::Corrupt, "corrupt file: an attribute section's value layout is invalid");
    if (a.semantic == AttributeSemantic::TexCoord) {
        a.uvOrigin[0] = in.f64("texture coordinate origin");
        a.uvOrigin[1] = in.f64("texture coordinate origin");
        a.uvStep = in.f64("texture coordinate step");
        if (!std::isfinite(a.uvOrigin[0]) || !std::isfinite(a.uvOrigin[1]) || !std::isfinite(a.uvStep) || !(a.uvStep > 0))
            throw Error(ErrorKind::Corrupt, "corrupt file: the texture coordinate grid is not finite");
    }
    const std::vector<AttributePredictor> allowed = predictorsFor(a);
    if (std::find(allowed.begin(), allowed.end(), AttributePredictor(predictor)) == allowed.end())
        throw Error(ErrorKind::Corrupt, "corrupt file: attribute predictor " + std::to_string(predictor) + " does not fit its attribute");
    const bool zeroFlags = (flags & kFlagZeroNormals) != 0;
    if (zeroFlags && a.semantic != AttributeSemantic::Normal)
        throw Error(ErrorKind::Corrupt, "corrupt file: zero flags on an attribute that is not a normal");
    const size_t D = size_t(a.components);
    RangeDecoder coder(data + in.offset(), in.remaining());
    Reader io{coder};
    const size_t faces = mesh.triangles.size() / 3;
    if (a.layout == AttributeLayout::Face) {
        ResidualCoder residuals(a.components, a.bits);
        a.values.assign(faces * D, 0);
        uint32_t p[kMaxComponents];
        for (uint32_t f = 0; f < faces; ++f) {
            predictFace(mesh, AttributePredictor(predictor), a.values, D, f, p);
            residuals.code(io, p, &a.values[size_t(f) * D]);
        }
    } else {
        WedgeWalk walk(mesh, a, AttributePredictor(predictor));
        std::vector<uint8_t> seam(usesWedges(a.layout) ? mesh.corners.interiorEdges.size() : 0, 0);
        codeWedgeLayout(io, walk, seam);
        codeWedges(io, walk, zeroFlags);
        // Back to elements.
        const size_t corners = mesh.triangles.size();
        const size_t elements = a.layout == AttributeLayout::Vertex ? mesh.vertexCount
                                : a.layout == AttributeLayout::Corner ? corners
                                                                      : corners + mesh.vertexCount;
        a.values.assign(elements * D, 0);
        if (zeroFlags) a.zero.assign(elements, 0);
        for (size_t c = 0; c < corners; ++c) {
            const uint32_t w = walk.wedgeOf[c];
            const size_t element = a.layout == AttributeLayout::Vertex ? size_t(mesh.triangles[c]) : c;
            for (size_t j = 0; j < D; ++j) a.values[element * D + j] = walk.values[size_t(w) * D + j];
            if (zeroFlags) a.zero[element] = walk.zero[w];
        }
        const size_t base = a.layout == AttributeLayout::WeldedVertex ? corners : 0;
        for (size_t i = 0; i < walk.isolated.size(); ++i) {
            const size_t w = walk.cornerWedges + i, element = base + walk.isolated[i];
            for (size_t j = 0; j < D; ++j) a.values[element * D + j] = walk.values[w * D + j];
            if (zeroFlags) a.zero[element] = walk.zero[w];
        }
    }
    if (coder.bytesPastEnd() > 0) throw Error(ErrorKind::Corrupt, "corrupt file: an attribute section ends before its last value");
    return a;
}

}  // namespace drm
