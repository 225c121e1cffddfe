// The codec options a MeshLab user can set, as MeshLab parameters.
//
// Shared by the save dialog (io_drm) and the rank filter (filter_drm) so both
// offer the same names, ranges and defaults as `drm encode` / `drm ranks`;
// the names are what .mlx filter scripts refer to.
#ifndef DRM_MESHLAB_ENCODE_PARAMETERS_H
#define DRM_MESHLAB_ENCODE_PARAMETERS_H

#include "bridge/meshlab_api.h"

#include <drmcodec/drmcodec.h>

namespace drm_meshlab {

extern const char* const kBitsParameter;             // RichInt, drm::kMin..kMaxQuantizationBits
extern const char* const kPredictorParameter;        // RichEnum: auto, parallelogram, midpoint
extern const char* const kKeepVertexOrderParameter;  // RichBool
extern const char* const kVerifyParameter;           // RichBool: EncodeOptions::verify
// The labels the dialogs show; error messages name parameters by them.
extern const char* const kBitsLabel;
extern const char* const kPredictorLabel;
extern const char* const kKeepVertexOrderLabel;
extern const char* const kVerifyLabel;

// Adds the quantization bits and the predictor, with the codec's defaults.
void addQuantizationAndPredictor(RichParameterList& parameters);
// Adds "keep vertex order" (off by default, as in `drm encode`).
void addKeepVertexOrder(RichParameterList& parameters);
// Adds "verify" (off by default, as in `drm encode`): decode what was
// written and compare it with the mesh before replacing the file.
void addVerify(RichParameterList& parameters);

// The codec's default options with those of the parameters present in
// `parameters` applied. Throws drm::Error naming the parameter by its label
// ("Quantization bits must be between 1 and 21, not 0", the range from drmcodec.h) when a value
// is out of range, so a bad .mlx value is refused with a sentence, not by
// an assertion deep in the codec.
drm::EncodeOptions encodeOptionsFrom(const RichParameterList& parameters);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_ENCODE_PARAMETERS_H
