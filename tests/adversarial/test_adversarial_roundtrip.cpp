// Every adversarial mesh, with every option set, decodes to the input:
// same vertex and face counts, same grid points, same oriented triangles.
#include <drmcodec/drmcodec.h>

#include <gtest/gtest.h>

#include <numeric>
#include <tuple>

#include "adversarial_meshes.h"
#include "adversarial_options.h"
#include "mesh_compare.h"

namespace adversarial {
namespace {

class AdversarialRoundTrip : public ::testing::TestWithParam<std::tuple<size_t, size_t>> {
protected:
    const AdversarialMesh& mesh() const { return adversarialMeshes()[std::get<0>(GetParam())]; }
    const drm::EncodeOptions& options() const { return adversarialOptions()[std::get<1>(GetParam())].options; }
};

TEST_P(AdversarialRoundTrip, DecodesToTheInput) {
    const drm::Mesh& input = mesh().mesh;
    const drm::Encoded encoded = drm::encode(input, options());
    const drm::Decoded decoded = drm::decode(encoded.bytes);
    EXPECT_TRUE(isLosslessRoundTrip(input, options().bits, encoded, decoded));
    if (keepsInputOrder(options())) {
        std::vector<uint32_t> identity(input.vertexCount());
        std::iota(identity.begin(), identity.end(), 0u);
        EXPECT_EQ(encoded.vertexOrder, identity) << "this option set promises the input vertex order";
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, AdversarialRoundTrip,
                         ::testing::Combine(::testing::Range<size_t>(0, adversarialMeshes().size()),
                                            ::testing::Range<size_t>(0, adversarialOptions().size())),
                         [](const ::testing::TestParamInfo<std::tuple<size_t, size_t>>& info) {
                             return adversarialMeshes()[std::get<0>(info.param)].name + "__" +
                                    adversarialOptions()[std::get<1>(info.param)].name;
                         });

}  // namespace
}  // namespace adversarial
