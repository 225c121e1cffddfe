#include "mesh/face_correspondence.h"

#include <algorithm>
#include <array>

#include "drmcodec/drmcodec.h"

namespace drm {
namespace {

struct Keyed {
    std::array<uint32_t, 3> key;  // the smallest rotation
    uint32_t face;
    uint8_t shift;  // key[j] = face corner (shift + j) % 3
};

// The faces by key, faces with equal keys in face order. A key begins with
// its face's smallest vertex: a counting sort on that places every face,
// then each run (the few faces around one vertex) is sorted by the rest. A
// stable sort of all faces would take about 3 % of an encoding's
// instructions; this takes no more memory than the keys and one count a
// vertex (the sort's buffer would take half the keys again).
Keyed keyOf(const std::vector<uint32_t>& t, uint32_t f) {
    const uint32_t* c = &t[3 * size_t(f)];
    Keyed best{{c[0], c[1], c[2]}, f, 0};
    for (uint8_t r = 1; r < 3; ++r) {
        const std::array<uint32_t, 3> k = {c[r], c[(r + 1) % 3], c[(r + 2) % 3]};
        if (k < best.key) best = {k, f, r};
    }
    return best;
}

std::vector<Keyed> keyed(const std::vector<uint32_t>& t) {
    const size_t faces = t.size() / 3;
    uint32_t vertices = 0;
    for (uint32_t v : t) vertices = std::max(vertices, v + 1);
    // end[v]: where the faces whose smallest vertex is v end, once placed
    // (they begin where those of v - 1 end).
    std::vector<uint32_t> end(vertices, 0);
    for (size_t f = 0; f < faces; ++f) ++end[std::min({t[3 * f], t[3 * f + 1], t[3 * f + 2]})];
    uint32_t placed = 0;
    for (uint32_t& e : end) {
        const uint32_t count = e;
        e = placed;  // for now where the run begins; placing moves it to the end
        placed += count;
    }
    std::vector<Keyed> out(faces);
    for (uint32_t f = 0; f < faces; ++f) {
        const Keyed k = keyOf(t, f);
        out[end[k.key[0]]++] = k;  // in face order within each vertex
    }
    // Each run by insertion, which keeps equal keys in face order; a long
    // run (a vertex shared by many faces: a cone's apex, a fan) by a stable
    // sort, so that no run costs its square.
    const auto byKey = [](const Keyed& a, const Keyed& b) { return a.key < b.key; };
    for (size_t v = 0; v < vertices; ++v) {
        const size_t first = v == 0 ? 0 : end[v - 1], last = end[v];
        if (last - first > 32) {
            std::stable_sort(out.begin() + ptrdiff_t(first), out.begin() + ptrdiff_t(last), byKey);
            continue;
        }
        for (size_t i = first + 1; i < last; ++i) {
            const Keyed moving = out[i];
            size_t j = i;
            for (; j > first && byKey(moving, out[j - 1]); --j) out[j] = out[j - 1];
            out[j] = moving;
        }
    }
    return out;
}

}  // namespace

void matchFaces(const std::vector<uint32_t>& input, const std::vector<uint32_t>& decoded,
                std::vector<uint32_t>& faceOrder, std::vector<uint8_t>& rotation) {
    if (input.size() != decoded.size()) throw Error(ErrorKind::Internal, "internal error: the decoded faces are not the input's");
    const std::vector<Keyed> a = keyed(input), b = keyed(decoded);
    faceOrder.assign(b.size(), 0);
    rotation.assign(b.size(), 0);
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].key != b[i].key) throw Error(ErrorKind::Internal, "internal error: the decoded faces are not the input's");
        // decoded corner (b.shift + j) = input corner (a.shift + j), so decoded corner k is input corner
        // k - b.shift + a.shift.
        faceOrder[b[i].face] = a[i].face;
        rotation[b[i].face] = uint8_t((a[i].shift + 3 - b[i].shift) % 3);
    }
}

}  // namespace drm
