#include "vertex_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <flann/flann.hpp>

namespace drm {
namespace {

// Collects every point FLANN offers within a fixed squared radius.
class CollectWithin : public flann::ResultSet<float> {
public:
    CollectWithin(float radius2, std::vector<uint32_t>& out) : radius2_(radius2), out_(out) {}
    bool full() const override { return true; }
    void addPoint(float dist, size_t index) override {
        if (dist <= radius2_) out_.push_back(uint32_t(index));
    }
    float worstDist() const override { return radius2_; }

private:
    float radius2_;
    std::vector<uint32_t>& out_;
};

// Float search error: coordinates up to 2^22 in magnitude round to float
// with at most 0.25 units of error per axis, and the sums of squares carry a
// few ulps; padding the radius by 2 units and 1e-5 relative covers both.
double paddedRadius2(double radius) {
    const double padded = radius + 2.0;
    return padded * padded * (1.0 + 1e-5);
}

}  // namespace

struct VertexIndex::Impl {
    std::vector<float> points;
    std::unique_ptr<flann::KDTreeSingleIndex<flann::L2_Simple<float>>> tree;
};

VertexIndex::VertexIndex(const std::vector<int32_t>& grid) : impl_(new Impl) {
    const size_t count = grid.size() / 3;
    present_ = count;
    if (count == 0) return;
    impl_->points.assign(grid.begin(), grid.end());
    flann::Matrix<float> matrix(impl_->points.data(), count, 3);
    impl_->tree.reset(new flann::KDTreeSingleIndex<flann::L2_Simple<float>>(
        matrix, flann::KDTreeSingleIndexParams(8, /*reorder=*/true)));
    impl_->tree->buildIndex();
}

VertexIndex::~VertexIndex() = default;

void VertexIndex::remove(uint32_t v) {
    if (!impl_->tree) return;
    impl_->tree->removePoint(v);
    --present_;
}

void VertexIndex::collectNear(Vec3 q, double radius, std::vector<uint32_t>& out) const {
    out.clear();
    if (!impl_->tree || present_ == 0) return;
    const float query[3] = {float(q.x), float(q.y), float(q.z)};
    const double r2 = std::min(paddedRadius2(radius), double(std::numeric_limits<float>::max()));
    CollectWithin collector(float(r2), out);
    impl_->tree->findNeighbors(collector, query, flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED, 0.0f));
}

double VertexIndex::radiusHolding(Vec3 q, size_t k) const {
    if (!impl_->tree || k == 0 || present_ < k) return std::numeric_limits<double>::infinity();
    // FLANN's k-nearest result set inserts in O(k); beyond a few dozen
    // neighbours a smaller estimate, grown by the caller, is much cheaper.
    k = std::min<size_t>(k, 48);
    const float query[3] = {float(q.x), float(q.y), float(q.z)};
    flann::KNNSimpleResultSet<float> nearest(k);
    impl_->tree->findNeighbors(nearest, query, flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED, 0.0f));
    const double worst = nearest.worstDist();
    if (!(worst < std::numeric_limits<float>::max())) return std::numeric_limits<double>::infinity();
    return std::sqrt(worst) + 2.0;
}

}  // namespace drm
