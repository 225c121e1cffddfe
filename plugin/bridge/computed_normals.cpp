#include "bridge/computed_normals.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace drm_meshlab {

const double kComputedNormalTolerance = 0.08 * 3.14159265358979323846 / 180.0;

namespace {

struct Vector {
    double x = 0, y = 0, z = 0;
};

Vector difference(const CVertexO& a, const CVertexO& b) {
    return {double(a.cP()[0]) - b.cP()[0], double(a.cP()[1]) - b.cP()[1], double(a.cP()[2]) - b.cP()[2]};
}

double length(const Vector& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

Vector unit(const Vector& v) {
    const double n = length(v);
    return n > 0 ? Vector{v.x / n, v.y / n, v.z / n} : Vector{};
}

double dot(const Vector& a, const Vector& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The angle between unit vectors a and b (0 if either is zero), as
// vcg's AngleN.
double angle(const Vector& a, const Vector& b) {
    const double c = dot(a, b);
    return std::acos(c > 1 ? 1 : (c < -1 ? -1 : c));
}

// Whether a and b point the same way within kComputedNormalTolerance; two
// zero vectors count as the same, a zero and a non-zero one do not.
bool sameDirection(const Vector& a, const Vector& b) {
    static const double minimumCosine = std::cos(kComputedNormalTolerance);
    const Vector ua = unit(a), ub = unit(b);
    const bool aZero = length(ua) == 0, bZero = length(ub) == 0;
    if (aZero || bZero) return aZero == bZero;
    return dot(ua, ub) >= minimumCosine;
}

// True when two live vertices at different positions lie closer than
// `step` on every axis: the file's grid may then merge them into one vertex.
bool distinctPositionsCloserThan(const CMeshO& cm, double step) {
    using Cell = std::tuple<long long, long long, long long>;
    std::vector<std::pair<Cell, size_t>> cells;
    for (size_t i = 0; i < cm.vert.size(); ++i) {
        if (cm.vert[i].IsD()) continue;
        const auto& p = cm.vert[i].cP();
        cells.push_back({Cell{(long long)std::floor(p[0] / step), (long long)std::floor(p[1] / step),
                              (long long)std::floor(p[2] / step)},
                         i});
    }
    std::sort(cells.begin(), cells.end());
    for (const auto& entry : cells) {
        const auto& p = cm.vert[entry.second].cP();
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz) {
                    const Cell near{std::get<0>(entry.first) + dx, std::get<1>(entry.first) + dy,
                                    std::get<2>(entry.first) + dz};
                    auto it = std::lower_bound(cells.begin(), cells.end(), std::make_pair(near, size_t(0)));
                    for (; it != cells.end() && it->first == near; ++it) {
                        const auto& q = cm.vert[it->second].cP();
                        if (q == p) continue;
                        if (std::fabs(double(q[0]) - p[0]) < step && std::fabs(double(q[1]) - p[1]) < step &&
                            std::fabs(double(q[2]) - p[2]) < step)
                            return true;
                    }
                }
    }
    return false;
}

}  // namespace

bool normalsAreComputedFromFaces(const CMeshO& cm, double mergeStep) {
    if (cm.fn == 0) return false;
    // Non-finite positions (which the codec refuses) would also break the
    // orderings below.
    for (const CVertexO& v : cm.vert)
        if (!v.IsD() && !(std::isfinite(v.cP()[0]) && std::isfinite(v.cP()[1]) && std::isfinite(v.cP()[2])))
            return false;
    const bool verticesMayMerge = mergeStep > 0;
    if (verticesMayMerge && distinctPositionsCloserThan(cm, mergeStep)) return false;
    std::vector<Vector> computed(cm.vert.size());
    for (const CFaceO& f : cm.face) {
        if (f.IsD()) continue;
        const Vector e0 = difference(*f.cV(1), *f.cV(0)), e1 = difference(*f.cV(2), *f.cV(1)),
                     e2 = difference(*f.cV(0), *f.cV(2));
        const Vector normal = unit({e0.y * -e2.z - e0.z * -e2.y, e0.z * -e2.x - e0.x * -e2.z,
                                    e0.x * -e2.y - e0.y * -e2.x});
        const Vector u0 = unit(e0), u1 = unit(e1), u2 = unit(e2);
        const double corner[3] = {angle(u0, {-u2.x, -u2.y, -u2.z}), angle({-u0.x, -u0.y, -u0.z}, u1),
                                  angle({-u1.x, -u1.y, -u1.z}, u2)};
        for (int k = 0; k < 3; ++k) {
            Vector& n = computed[size_t(f.cV(k) - &cm.vert[0])];
            n.x += normal.x * corner[k];
            n.y += normal.y * corner[k];
            n.z += normal.z * corner[k];
        }
    }
    // Vertices at one position (a seam of texture coordinates or of normals)
    // may come back from the file as one vertex: their normals must then also
    // match the normal computed over all their faces.
    std::vector<size_t> order;
    for (size_t i = 0; i < cm.vert.size(); ++i)
        if (!cm.vert[i].IsD()) order.push_back(i);
    const auto position = [&cm](size_t i) {
        const auto& p = cm.vert[i].cP();
        return std::make_tuple(p[0], p[1], p[2]);
    };
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return position(a) < position(b); });
    for (size_t first = 0; first < order.size();) {
        size_t last = first + 1;
        while (last < order.size() && position(order[last]) == position(order[first])) ++last;
        Vector shared;
        for (size_t k = first; k < last; ++k) {
            const Vector& n = computed[order[k]];
            shared.x += n.x;
            shared.y += n.y;
            shared.z += n.z;
        }
        for (size_t k = first; k < last; ++k) {
            const CVertexO& v = cm.vert[order[k]];
            const Vector own{double(v.cN()[0]), double(v.cN()[1]), double(v.cN()[2])};
            if (!sameDirection(own, computed[order[k]])) return false;
            if (verticesMayMerge && !sameDirection(own, shared)) return false;
        }
        first = last;
    }
    return true;
}

double gridStep(const CMeshO& cm, int bits) {
    double low[3] = {0, 0, 0}, high[3] = {0, 0, 0};
    bool first = true;
    for (const CVertexO& v : cm.vert) {
        if (v.IsD()) continue;
        for (int a = 0; a < 3; ++a) {
            const double x = v.cP()[a];
            low[a] = first ? x : std::min(low[a], x);
            high[a] = first ? x : std::max(high[a], x);
        }
        first = false;
    }
    const double side = std::max({high[0] - low[0], high[1] - low[1], high[2] - low[2]});
    return side / (std::ldexp(1.0, bits) - 1.0);
}

}  // namespace drm_meshlab
