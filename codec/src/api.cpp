// Small public helpers: names, parsing and derived figures.
#include <string>

#include "drm/drm.h"

namespace drm {

const char* version() { return "0.1.0"; }

const char* predictorName(Predictor p) {
    switch (p) {
        case Predictor::Auto: return "auto";
        case Predictor::Parallelogram: return "parallelogram";
        case Predictor::Midpoint: return "midpoint";
    }
    return "unknown";
}

Predictor parsePredictor(const std::string& name) {
    for (Predictor p : {Predictor::Auto, Predictor::Parallelogram, Predictor::Midpoint})
        if (name == predictorName(p)) return p;
    throw Error("unknown predictor '" + name + "' (use auto, parallelogram or midpoint)");
}

const char* geometryCoderName(GeometryCoder g) {
    switch (g) {
        case GeometryCoder::Raw: return "raw";
        case GeometryCoder::SpanningTree: return "tree";
    }
    return "unknown";
}

GeometryCoder parseGeometryCoder(const std::string& name) {
    for (GeometryCoder g : {GeometryCoder::SpanningTree, GeometryCoder::Raw})
        if (name == geometryCoderName(g)) return g;
    throw Error("unknown geometry coder '" + name + "' (use tree or raw)");
}

namespace {
double perVertex(uint64_t bytes, uint64_t vertices) { return vertices ? 8.0 * double(bytes) / double(vertices) : 0.0; }
}  // namespace

double Stats::connectivityBitsPerVertex() const { return perVertex(connectivityBytes, vertices); }
double Stats::geometryBitsPerVertex() const { return perVertex(geometryBytes, vertices); }
double Stats::totalBitsPerVertex() const { return perVertex(totalBytes, vertices); }

}  // namespace drm
