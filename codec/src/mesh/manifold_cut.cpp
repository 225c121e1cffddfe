#include "mesh/manifold_cut.h"

#include <algorithm>
#include <array>

#include "drmcodec/drmcodec.h"
#include "common.h"
#include "connectivity/halfedge_map.h"

namespace drm {
namespace {

// Slot 3f + e is edge e of kept face f, from corner e to corner e + 1; it is
// also the name of corner e.
uint32_t nextSlot(uint32_t s) { return s - s % 3 + (s % 3 + 1) % 3; }

struct Joins {
    std::vector<uint32_t> partner;  // slot -> the slot across the edge, or kNoIndex
    std::vector<uint8_t> sameDirection;

    void cut(uint32_t s) {
        const uint32_t p = partner[s];
        if (p == kNoIndex) return;
        partner[s] = partner[p] = kNoIndex;
    }
};

// Joins every pair of faces that are alone on their edge.
Joins findJoins(const std::vector<uint32_t>& t) {
    struct EdgeUse {
        uint64_t key;
        uint32_t slot;
        bool operator<(const EdgeUse& o) const { return key != o.key ? key < o.key : slot < o.slot; }
    };
    std::vector<EdgeUse> uses(t.size());
    for (uint32_t s = 0; s < t.size(); ++s) {
        const uint32_t a = t[s], b = t[nextSlot(s)];
        uses[s] = {(uint64_t(std::min(a, b)) << 32) | std::max(a, b), s};
    }
    std::sort(uses.begin(), uses.end());
    Joins joins;
    joins.partner.assign(t.size(), kNoIndex);
    joins.sameDirection.assign(t.size(), 0);
    for (size_t i = 0; i < uses.size();) {
        size_t j = i + 1;
        while (j < uses.size() && uses[j].key == uses[i].key) ++j;
        if (j - i == 2) {
            const uint32_t s = uses[i].slot, p = uses[i + 1].slot;
            joins.partner[s] = p;
            joins.partner[p] = s;
            joins.sameDirection[s] = joins.sameDirection[p] = uint8_t(t[s] == t[p]);
        }
        i = j;
    }
    return joins;
}

// Orients each piece like its first face (in input order); cuts joins that
// would need a face both ways round. Returns flip bits per face.
std::vector<uint8_t> orient(Joins& joins, size_t faceCount) {
    std::vector<uint8_t> flip(faceCount, 0), seen(faceCount, 0);
    std::vector<uint32_t> queue;
    for (uint32_t root = 0; root < faceCount; ++root) {
        if (seen[root]) continue;
        seen[root] = 1;
        queue.assign(1, root);
        for (size_t q = 0; q < queue.size(); ++q) {
            const uint32_t f = queue[q];
            for (uint32_t s = 3 * f; s < 3 * f + 3; ++s) {
                const uint32_t p = joins.partner[s];
                if (p == kNoIndex) continue;
                const uint32_t g = p / 3;
                const uint8_t wanted = flip[f] ^ joins.sameDirection[s];
                if (!seen[g]) {
                    seen[g] = 1;
                    flip[g] = wanted;
                    queue.push_back(g);
                } else if (flip[g] != wanted) {
                    joins.cut(s);
                }
            }
        }
    }
    return flip;
}

// Numbers the fans: corners linked by joins share a vertex; the first fan
// of each vertex (by corner order) keeps its index, the others get copies.
// Returns the new vertex of every corner; fills copyOf.
std::vector<uint32_t> numberFans(const std::vector<uint32_t>& t, const Joins& joins, size_t vertexCount,
                                 std::vector<uint32_t>& copyOf) {
    UnionFind fans(t.size());
    for (uint32_t s = 0; s < t.size(); ++s) {
        const uint32_t p = joins.partner[s];
        if (p == kNoIndex || p < s) continue;
        // Edge s runs a -> b. If p runs the same way its corners pair up
        // in the same order, otherwise crosswise.
        if (joins.sameDirection[s]) {
            fans.join(s, p);
            fans.join(nextSlot(s), nextSlot(p));
        } else {
            fans.join(s, nextSlot(p));
            fans.join(nextSlot(s), p);
        }
    }
    copyOf.clear();
    std::vector<uint32_t> vertexOfFan(t.size(), kNoVertex), corner(t.size());
    std::vector<uint8_t> taken(vertexCount, 0);
    for (uint32_t c = 0; c < t.size(); ++c) {
        const uint32_t fan = fans.root(c);
        if (vertexOfFan[fan] == kNoVertex) {
            const uint32_t v = t[c];
            if (!taken[v]) {
                taken[v] = 1;
                vertexOfFan[fan] = v;
            } else {
                if (vertexCount + copyOf.size() >= kNoVertex)
                    throw Error(ErrorKind::InvalidInput, "the mesh is too large to cut into manifold pieces: over 2^32-2 vertices");
                vertexOfFan[fan] = uint32_t(vertexCount + copyOf.size());
                copyOf.push_back(v);
            }
        }
        corner[c] = vertexOfFan[fan];
    }
    return corner;
}


// The rotation of a face that starts at its smallest index: two faces
// over the same vertices are equal or reversed exactly when these are.
std::array<uint32_t, 3> canonical(const uint32_t* v) {
    if (v[1] < v[0] && v[1] < v[2]) return {v[1], v[2], v[0]};
    if (v[2] < v[0] && v[2] < v[1]) return {v[2], v[0], v[1]};
    return {v[0], v[1], v[2]};
}

// For each input face: the earlier face over the same three vertices, or
// kNoIndex.
std::vector<uint32_t> findRepeatedFaces(const std::vector<uint32_t>& triangles) {
    const size_t faceCount = triangles.size() / 3;
    std::vector<std::array<uint32_t, 4>> sorted(faceCount);  // sorted vertices, face
    for (size_t f = 0; f < faceCount; ++f) {
        std::array<uint32_t, 4> key = {triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2], uint32_t(f)};
        std::sort(key.begin(), key.begin() + 3);
        sorted[f] = key;
    }
    std::sort(sorted.begin(), sorted.end());
    std::vector<uint32_t> earlier(faceCount, kNoIndex);
    size_t first = 0;  // of the run of faces over the same vertices
    for (size_t i = 1; i < faceCount; ++i) {
        if (std::equal(sorted[i].begin(), sorted[i].begin() + 3, sorted[first].begin()))
            earlier[sorted[i][3]] = sorted[first][3];
        else
            first = i;
    }
    return earlier;
}

}  // namespace

ManifoldCut cutIntoManifold(const std::vector<uint32_t>& triangles, size_t vertexCount) {
    ManifoldCut cut;
    const std::vector<uint32_t> earlier = findRepeatedFaces(triangles);
    std::vector<uint32_t> keptIndex(triangles.size() / 3, kNoIndex);
    std::vector<uint32_t> kept;  // kept faces, input orientation
    for (size_t f = 0; f < triangles.size() / 3; ++f) {
        const uint32_t* v = &triangles[3 * f];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
            cut.looseTriangles.insert(cut.looseTriangles.end(), v, v + 3);
            cut.looseInputFace.push_back(uint32_t(f));
        } else if (earlier[f] != kNoIndex) {
            const uint32_t g = earlier[f];  // kept: the first of its vertex set
            cut.duplicateOf.push_back(keptIndex[g]);
            cut.duplicateReversed.push_back(uint8_t(canonical(v) != canonical(&triangles[3 * size_t(g)])));
            cut.duplicateInputFace.push_back(uint32_t(f));
        } else {
            keptIndex[f] = uint32_t(cut.inputFace.size());
            kept.insert(kept.end(), v, v + 3);
            cut.inputFace.push_back(uint32_t(f));
        }
    }
    const size_t faceCount = cut.inputFace.size();

    Joins joins = findJoins(kept);
    cut.flipped = orient(joins, faceCount);
    cut.flippedCount = size_t(std::count(cut.flipped.begin(), cut.flipped.end(), 1));

    // Each pass detaches every face that repeats a directed edge of an
    // earlier face. Detaching only splits fans, so vertices that differed
    // stay different and a detached face shares no vertex with anyone: the
    // second pass finds nothing (the bound is a guard, not a tuning).
    for (int pass = 0;; ++pass) {
        std::vector<uint32_t> corner = numberFans(kept, joins, vertexCount, cut.copyOf);
        cut.triangles.resize(kept.size());
        for (size_t f = 0; f < faceCount; ++f) {
            const uint32_t* c = &corner[3 * f];
            if (cut.flipped[f]) {
                cut.triangles[3 * f] = c[0], cut.triangles[3 * f + 1] = c[2], cut.triangles[3 * f + 2] = c[1];
            } else {
                cut.triangles[3 * f] = c[0], cut.triangles[3 * f + 1] = c[1], cut.triangles[3 * f + 2] = c[2];
            }
        }
        HalfEdgeMap directed(cut.triangles.size());
        bool detached = false;
        for (uint32_t f = 0; f < faceCount; ++f) {
            bool clash = false;
            for (int k = 0; k < 3; ++k)
                clash |= directed.contains(cut.triangles[3 * f + k], cut.triangles[3 * f + (k + 1) % 3]);
            if (clash) {
                for (uint32_t s = 3 * f; s < 3 * f + 3; ++s) joins.cut(s);
                detached = true;
                continue;
            }
            for (int k = 0; k < 3; ++k)
                directed.insert(cut.triangles[3 * f + k], cut.triangles[3 * f + (k + 1) % 3], f);
        }
        if (!detached) break;
        if (pass > 2) throw Error(ErrorKind::Internal, "internal error: cutting the mesh into manifold pieces did not converge");
    }
    return cut;
}

}  // namespace drm
