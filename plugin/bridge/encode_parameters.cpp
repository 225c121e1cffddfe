#include "bridge/encode_parameters.h"

#include <string>

namespace drm_meshlab {

const char* const kBitsParameter = "QuantizationBits";
const char* const kPredictorParameter = "Predictor";
const char* const kKeepVertexOrderParameter = "KeepVertexOrder";

namespace {

const int kMinBits = 1;
const int kMaxBits = 21;

// The enum's entries in the order of the list MeshLab shows; parsed back
// through drm::parsePredictor so the names cannot drift from the codec's.
const drm::Predictor kPredictorChoices[] = {drm::Predictor::Auto, drm::Predictor::Parallelogram,
                                            drm::Predictor::Midpoint};
const int kPredictorChoiceCount = int(sizeof(kPredictorChoices) / sizeof(kPredictorChoices[0]));

int defaultPredictorIndex() {
    const drm::Predictor standard = drm::EncodeOptions().predictor;
    for (int i = 0; i < kPredictorChoiceCount; ++i)
        if (kPredictorChoices[i] == standard) return i;
    return 0;
}

}  // namespace

void addQuantizationAndPredictor(RichParameterList& parameters) {
    parameters.addParam(RichInt(
        kBitsParameter, drm::EncodeOptions().bits, "Quantization bits",
        QString("Bits per coordinate axis (%1 to %2). Positions are snapped to a grid of "
                "2^bits - 1 steps over the longest side of the bounding box; 12 is the paper's setting.")
            .arg(kMinBits)
            .arg(kMaxBits)));
    QStringList names;
    for (drm::Predictor p : kPredictorChoices) names << drm::predictorName(p);
    parameters.addParam(RichEnum(kPredictorParameter, defaultPredictorIndex(), names, "Apex predictor",
                                 "Where the traversal expects each new triangle's third vertex: "
                                 "parallelogram (reflect the opposite vertex over the edge), midpoint "
                                 "(above the edge's middle), or auto (chosen per mesh, as in the paper)."));
}

void addKeepVertexOrder(RichParameterList& parameters) {
    parameters.addParam(RichBool(kKeepVertexOrderParameter, drm::EncodeOptions().keepVertexOrder,
                                 "Keep vertex order",
                                 "Store the permutation back to this mesh's vertex order, so the file "
                                 "opens with the same vertex indices (costs a few bits per vertex). "
                                 "Off: vertices come back in the order the geometry coder chose."));
}

drm::EncodeOptions encodeOptionsFrom(const RichParameterList& parameters) {
    drm::EncodeOptions options;
    if (parameters.hasParameter(kBitsParameter)) {
        const int bits = parameters.getInt(kBitsParameter);
        if (bits < kMinBits || bits > kMaxBits)
            throw drm::Error(std::string(kBitsParameter) + " must be between " + std::to_string(kMinBits) +
                             " and " + std::to_string(kMaxBits) + ", not " + std::to_string(bits));
        options.bits = bits;
    }
    if (parameters.hasParameter(kPredictorParameter)) {
        const int index = parameters.getEnum(kPredictorParameter);
        if (index < 0 || index >= kPredictorChoiceCount)
            throw drm::Error(std::string(kPredictorParameter) + " must be 0 (auto), 1 (parallelogram) or 2 "
                             "(midpoint), not " + std::to_string(index));
        options.predictor = kPredictorChoices[index];
    }
    if (parameters.hasParameter(kKeepVertexOrderParameter))
        options.keepVertexOrder = parameters.getBool(kKeepVertexOrderParameter);
    return options;
}

}  // namespace drm_meshlab
