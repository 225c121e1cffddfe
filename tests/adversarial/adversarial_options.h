// The encoder options every adversarial mesh is tried with: the defaults,
// the kept vertex order, the raw and refine geometry coders, and coarse grids
// on which many vertices share a grid point.
#ifndef DRM_TEST_ADVERSARIAL_OPTIONS_H
#define DRM_TEST_ADVERSARIAL_OPTIONS_H

#include <drmcodec/drmcodec.h>

#include <string>
#include <vector>

namespace adversarial {

struct NamedOptions {
    std::string name;  // a gtest name
    drm::EncodeOptions options;
};

// Built once, shared by every test that walks them.
inline const std::vector<NamedOptions>& adversarialOptions() {
    static const std::vector<NamedOptions> all = [] {
        std::vector<NamedOptions> sets;
        auto add = [&](const std::string& name, auto change) {
            drm::EncodeOptions o;
            change(o);
            sets.push_back({name, o});
        };
        add("default", [](drm::EncodeOptions&) {});
        add("keep_order", [](drm::EncodeOptions& o) { o.keepVertexOrder = true; });
        add("raw", [](drm::EncodeOptions& o) { o.geometry = drm::GeometryCoder::Raw; });
        add("raw_bits4", [](drm::EncodeOptions& o) {
            o.geometry = drm::GeometryCoder::Raw;
            o.bits = 4;
        });
        add("bits4", [](drm::EncodeOptions& o) { o.bits = 4; });
        add("bits1_keep_order", [](drm::EncodeOptions& o) {
            o.bits = 1;
            o.keepVertexOrder = true;
        });
        add("refine_k2", [](drm::EncodeOptions& o) {
            o.geometry = drm::GeometryCoder::Refine;
            o.refineBits = 2;
        });
        add("refine_bits4_k3", [](drm::EncodeOptions& o) {  // the connectivity is ranked on a 1-bit grid
            o.geometry = drm::GeometryCoder::Refine;
            o.bits = 4;
            o.refineBits = 3;
        });
        add("refine_auto_keep_order", [](drm::EncodeOptions& o) {
            o.geometry = drm::GeometryCoder::Refine;
            o.keepVertexOrder = true;
        });
        add("topological", [](drm::EncodeOptions& o) { o.connectivity = drm::ConnectivityCoder::Topological; });
        add("topological_bits1_keep_order", [](drm::EncodeOptions& o) {
            o.connectivity = drm::ConnectivityCoder::Topological;
            o.bits = 1;
            o.keepVertexOrder = true;
        });
        add("ranks", [](drm::EncodeOptions& o) { o.connectivity = drm::ConnectivityCoder::Ranks; });
        add("paper_method", [](drm::EncodeOptions& o) {
            o.levers = drm::Levers::none();
            o.tryWithoutLevers = false;
        });
        return sets;
    }();
    return all;
}

// drmcodec.h: the raw coder and keepVertexOrder keep the input vertex order.
inline bool keepsInputOrder(const drm::EncodeOptions& o) {
    return o.keepVertexOrder || o.geometry == drm::GeometryCoder::Raw;
}

}  // namespace adversarial

#endif  // DRM_TEST_ADVERSARIAL_OPTIONS_H
