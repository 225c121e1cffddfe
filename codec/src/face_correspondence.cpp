#include "face_correspondence.h"

#include <algorithm>
#include <array>

#include "drm/drm.h"

namespace drm {
namespace {

struct Keyed {
    std::array<uint32_t, 3> key;  // the smallest rotation
    uint32_t face;
    uint8_t shift;  // key[j] = face corner (shift + j) % 3
};

std::vector<Keyed> keyed(const std::vector<uint32_t>& t) {
    std::vector<Keyed> out(t.size() / 3);
    for (uint32_t f = 0; f < out.size(); ++f) {
        const uint32_t* c = &t[3 * size_t(f)];
        Keyed best{{c[0], c[1], c[2]}, f, 0};
        for (uint8_t r = 1; r < 3; ++r) {
            const std::array<uint32_t, 3> k = {c[r], c[(r + 1) % 3], c[(r + 2) % 3]};
            if (k < best.key) best = {k, f, r};
        }
        out[f] = best;
    }
    std::stable_sort(out.begin(), out.end(), [](const Keyed& a, const Keyed& b) { return a.key < b.key; });
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
