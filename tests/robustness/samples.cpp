#include "samples.h"

#include <stdexcept>

#include "drmcodec/drmcodec.h"
#include "option_sets.h"
#include "test_meshes.h"

namespace drm_test {
namespace {

drm::EncodeOptions optionsNamed(const std::string& name) {
    for (const NamedOptions& o : optionSets())
        if (o.name == name) return o.options;
    throw std::invalid_argument("no option set named " + name);
}

Sample encoded(const std::string& meshName, const drm::Mesh& mesh, const std::string& optionsName) {
    return {meshName + "/" + optionsName, drm::encode(mesh, optionsNamed(optionsName)).bytes};
}

}  // namespace

const std::vector<Sample>& coreSamples() {
    // A mesh with a hole, several components and an isolated vertex, a
    // closed one, and one with a repairs section; default options and the
    // optional vertex order section.
    static const std::vector<Sample> core = [] {
        const drm::Mesh mixed = mixedMesh();
        const drm::Mesh sphere = icosphere(2);
        const drm::Mesh repaired = meshNeedingRepairs();
        return std::vector<Sample>{encoded("mixed", mixed, "default"), encoded("mixed", mixed, "keep-order"),
                                   encoded("icosphere", sphere, "default"), encoded("mixed", mixed, "raw"),
                                   encoded("needs-repairs", repaired, "default")};
    }();
    return core;
}

const std::vector<Sample>& samples() {
    static const std::vector<Sample> all = [] {
        std::vector<Sample> s = coreSamples();
        const drm::Mesh mixed = mixedMesh();
        for (const char* options : {"no-levers", "bits4", "bits1-raw", "raw-bits21-parallelogram",
                                    "midpoint-curvature", "gap-closing-only", "angle-only"})
            s.push_back(encoded("mixed", mixed, options));
        s.push_back(encoded("icosphere", icosphere(2), "keep-order"));
        s.push_back(encoded("tetrahedron", tetrahedron(), "default"));
        s.push_back(encoded("box-ring", boxRing(4), "confidence-only"));
        return s;
    }();
    return all;
}

}  // namespace drm_test
