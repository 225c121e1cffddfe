// The valid .drm files the robustness tests damage: small meshes made in
// code, encoded with option sets that between them set every header flag
// and use both geometry coders and the vertex-order section.
#ifndef DRM_TEST_SAMPLES_H
#define DRM_TEST_SAMPLES_H

#include <string>
#include <vector>

#include "verdicts.h"

namespace drm_test {

struct Sample {
    std::string name;  // mesh/options
    Bytes bytes;
};

// Encoded once per process.
const std::vector<Sample>& samples();

// The few samples that get the expensive exhaustive treatments.
const std::vector<Sample>& coreSamples();

}  // namespace drm_test

#endif  // DRM_TEST_SAMPLES_H
