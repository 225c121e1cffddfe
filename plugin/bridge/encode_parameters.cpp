#include "bridge/encode_parameters.h"

#include <string>

namespace drm_meshlab {

const char* const kBitsParameter = "QuantizationBits";
const char* const kPredictorParameter = "Predictor";
const char* const kKeepVertexOrderParameter = "KeepVertexOrder";
const char* const kBitsLabel = "Quantization bits";
const char* const kPredictorLabel = "Apex predictor";
const char* const kKeepVertexOrderLabel = "Keep vertex order";
const char* const kVerifyParameter = "VerifyAfterWriting";
const char* const kVerifyLabel = "Verify";

namespace {

// drmcodec.h's range, so the dialog, its help and its refusals say what the codec takes.
const int kMinBits = drm::kMinQuantizationBits;
const int kMaxBits = drm::kMaxQuantizationBits;

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
    // MeshLab shows this text both as the tooltip and, under Help, beside
    // the field in a narrow column the save dialog cuts after two lines:
    // short and complete; README.md's MeshLab section says more.
    parameters.addParam(RichInt(kBitsParameter, drm::EncodeOptions().bits, kBitsLabel,
                                QString("Grid bits per axis, %1 to %2 (%3: the paper's). Lossless on that grid.")
                                    .arg(kMinBits)
                                    .arg(kMaxBits)
                                    .arg(drm::kDefaultQuantizationBits)));
    QStringList names;
    for (drm::Predictor p : kPredictorChoices) names << drm::predictorName(p);
    parameters.addParam(RichEnum(kPredictorParameter, defaultPredictorIndex(), names, kPredictorLabel,
                                 "Guess of each new triangle's apex; auto picks the better per mesh."));
}

void addKeepVertexOrder(RichParameterList& parameters) {
    parameters.addParam(RichBool(kKeepVertexOrderParameter, drm::EncodeOptions().keepVertexOrder,
                                 kKeepVertexOrderLabel,
                                 "Reopen with this vertex order. Costs 5-12 bits per vertex; "
                                 "the save log says how much."));
}

void addVerify(RichParameterList& parameters) {
    parameters.addParam(RichBool(kVerifyParameter, drm::EncodeOptions().verify, kVerifyLabel,
                                 "Decode and compare before writing. Costs about half the save time again."));
}

drm::EncodeOptions encodeOptionsFrom(const RichParameterList& parameters) {
    drm::EncodeOptions options;
    if (parameters.hasParameter(kBitsParameter)) {
        const int bits = parameters.getInt(kBitsParameter);
        if (bits < kMinBits || bits > kMaxBits)
            throw drm::Error(drm::ErrorKind::InvalidInput, std::string(kBitsLabel) + " must be between " + std::to_string(kMinBits) + " and " +
                             std::to_string(kMaxBits) + ", not " + std::to_string(bits));
        options.bits = bits;
    }
    if (parameters.hasParameter(kPredictorParameter)) {
        const int index = parameters.getEnum(kPredictorParameter);
        if (index < 0 || index >= kPredictorChoiceCount) {
            // "0 (auto), 1 (parallelogram) or 2 (midpoint)": the codec's names.
            std::string choices;
            for (int i = 0; i < kPredictorChoiceCount; ++i)
                choices += std::string(i == 0 ? "" : (i + 1 == kPredictorChoiceCount ? " or " : ", ")) +
                           std::to_string(i) + " (" + drm::predictorName(kPredictorChoices[i]) + ")";
            throw drm::Error(drm::ErrorKind::InvalidInput,
                             std::string(kPredictorLabel) + " must be " + choices + ", not " + std::to_string(index));
        }
        options.predictor = kPredictorChoices[index];
    }
    if (parameters.hasParameter(kKeepVertexOrderParameter))
        options.keepVertexOrder = parameters.getBool(kKeepVertexOrderParameter);
    if (parameters.hasParameter(kVerifyParameter)) options.verify = parameters.getBool(kVerifyParameter);
    return options;
}

}  // namespace drm_meshlab
