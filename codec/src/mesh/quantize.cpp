// One cubic step over the bounding box: the largest extent is split into
// 2^bits - 1 steps and the other axes use the same step, so the grid keeps the
// mesh's proportions (distances on the grid are distances in the model).
#include "mesh/quantize.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace drm {

Grid makeGrid(const std::vector<float>& positions, int bits) {
    if (bits < kMinBits || bits > kMaxBits)
        throw Error(ErrorKind::InvalidInput, "quantization bits must be between " + std::to_string(kMinBits) + " and " +
                    std::to_string(kMaxBits) + ", not " + std::to_string(bits));
    if (positions.size() % 3 != 0) throw Error(ErrorKind::InvalidInput, "the position array does not hold whole xyz triples");
    if (positions.empty()) throw Error(ErrorKind::InvalidInput, "empty mesh: there are no vertices to encode");
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = positions[size_t(k)];
    for (size_t i = 0; i < positions.size(); ++i) {
        const double x = positions[i];
        if (!std::isfinite(x))
            throw Error(ErrorKind::InvalidInput, "vertex " + std::to_string(i / 3) + " has a non-finite coordinate (" +
                        (std::isnan(x) ? std::string("NaN") : std::string("infinity")) + ")");
        lo[i % 3] = std::min(lo[i % 3], x);
        hi[i % 3] = std::max(hi[i % 3], x);
    }
    Grid grid;
    grid.bits = bits;
    double extent = 0;
    for (int k = 0; k < 3; ++k) {
        grid.origin[k] = lo[k];
        extent = std::max(extent, hi[k] - lo[k]);
    }
    grid.step = extent > 0 ? extent / double(gridMax(bits)) : 1.0;
    return grid;
}

std::string gridProblem(const Grid& grid) {
    if (grid.bits < kMinBits || grid.bits > kMaxBits)
        return "quantization bits " + std::to_string(grid.bits) + " out of range " + std::to_string(kMinBits) + ".." +
               std::to_string(kMaxBits);
    for (double o : grid.origin)
        if (!std::isfinite(o) || !std::isfinite(float(o))) return "the bounding box origin is not a finite float";
    if (!std::isfinite(grid.step) || !(grid.step > 0)) return "the grid step is not a positive number";
    return "";
}

bool dequantize(const std::vector<int32_t>& q, const Grid& grid, std::vector<float>& positions, size_t* badVertex) {
    positions.resize(q.size());
    for (size_t i = 0; i < q.size(); ++i) {
        positions[i] = float(grid.origin[i % 3] + double(q[i]) * grid.step);
        if (!std::isfinite(positions[i])) {
            if (badVertex) *badVertex = i / 3;
            return false;
        }
    }
    return true;
}

std::vector<int32_t> quantize(const std::vector<float>& positions, const Grid& grid) {
    std::vector<int32_t> q(positions.size());
    const double top = gridMax(grid.bits);
    for (size_t i = 0; i < positions.size(); ++i) {
        const double x = positions[i];
        if (!std::isfinite(x)) throw Error(ErrorKind::InvalidInput, "vertex " + std::to_string(i / 3) + " has a non-finite coordinate");
        const double t = std::floor((x - grid.origin[i % 3]) / grid.step + 0.5);
        q[i] = int32_t(std::min(std::max(t, 0.0), top));
        // Near FLT_MAX the nearest grid point may lie past the float range
        // (an axis shorter than the longest can end half a step below its
        // last grid point): take the point below, so that every grid point
        // decodes to a finite float.
        while (q[i] > 0 && !std::isfinite(float(grid.origin[i % 3] + double(q[i]) * grid.step))) --q[i];
    }
    return q;
}

}  // namespace drm
