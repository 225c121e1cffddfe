#include "help_text.h"

#include <drmcodec/drmcodec.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace drm {
namespace cli {
namespace {

std::string range(int low, int high) { return std::to_string(low) + ".." + std::to_string(high); }
// 12 as "12", 11.5 as "11.5".
std::string decimal(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

// "a, b or c".
std::string listed(const std::vector<std::string>& names, const char* lastSeparator) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : (i + 1 == names.size() ? lastSeparator : ", ")) + names[i];
    return out;
}

std::vector<std::pair<std::string, std::string>> placeholders() {
    std::vector<std::string> levers;
    for (int l = 0; l < drm::kLeverCount; ++l) levers.push_back(drm::leverName(l));
    std::vector<std::string> predictors;
    for (drm::Predictor p : {drm::Predictor::Auto, drm::Predictor::Parallelogram, drm::Predictor::Midpoint})
        predictors.push_back(drm::predictorName(p));
    std::vector<std::string> coders = {drm::geometryCoderName(drm::GeometryCoder::Auto)};  // an option, not a stored coder
    for (drm::GeometryCoder g : {drm::GeometryCoder::SpanningTree, drm::GeometryCoder::Refine, drm::GeometryCoder::Sorted,
                                 drm::GeometryCoder::Raw})
        coders.push_back(drm::geometryCoderName(g));
    std::vector<std::string> autoLowBits;
    for (int k : drm::kAutoRefineLowBits) autoLowBits.push_back(std::to_string(k));
    const drm::EncodeOptions defaults;
    return {
        {"{bits}", range(drm::kMinQuantizationBits, drm::kMaxQuantizationBits)},
        {"{default-bits}", std::to_string(defaults.bits)},
        {"{refine-bits}", range(1, drm::kMaxRefineBits)},
        {"{tried-refine-bits}", range(1, drm::kMaxTriedRefineBits)},
        {"{normal-bits}", range(drm::kMinNormalBits, drm::kMaxNormalBits)},
        {"{default-normal-bits}", std::to_string(defaults.normalBits)},
        {"{uv-bits}", range(drm::kMinUvBits, drm::kMaxUvBits)},
        {"{default-uv-bits}", std::to_string(defaults.uvBits)},
        {"{levers}", listed(levers, ", ")},  // "filter, gap, context, angle, front, boundary"
        {"{predictors}", listed(predictors, " or ")},
        {"{default-predictor}", drm::predictorName(defaults.predictor)},
        {"{geometry-coders}", listed(coders, " or ")},
        {"{default-geometry}", drm::geometryCoderName(defaults.geometry)},
        {"{auto-refine-above}", decimal(drm::kAutoRefineAboveBitsPerVertex)},
        {"{auto-refine-low-bits}", listed(autoLowBits, " and ")},
        {"{auto-refine-gain}", std::to_string(drm::kAutoRefineMinimumGainPercent)},
    };
}

}  // namespace

std::string expandHelp(const char* text) {
    static const std::vector<std::pair<std::string, std::string>> names = placeholders();
    std::string out = text;
    for (const auto& name : names)
        for (size_t at = out.find(name.first); at != std::string::npos; at = out.find(name.first, at + name.second.size()))
            out.replace(at, name.first.size(), name.second);
    return out;
}

}  // namespace cli
}  // namespace drm
