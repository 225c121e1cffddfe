// Small public helpers: names, parsing and derived figures.
#include <algorithm>
#include <string>

#include "drmcodec/drmcodec.h"
#include "connectivity/connectivity_coders.h"
#include "geometry/geometry_coders.h"

namespace drm {

const char* version() { return "0.1.0"; }

const char* leverName(int lever) {
    static const char* const names[kLeverCount] = {"filter", "gap", "context", "angle", "front", "boundary"};
    return lever >= 0 && lever < kLeverCount ? names[lever] : nullptr;
}

const char* errorKindName(ErrorKind kind) {
    switch (kind) {
        case ErrorKind::InvalidInput: return "invalid input";
        case ErrorKind::Corrupt: return "corrupt";
        case ErrorKind::Unsupported: return "unsupported";
        case ErrorKind::Cancelled: return "cancelled";
        case ErrorKind::Io: return "i/o";
        case ErrorKind::Internal: return "internal";
    }
    return "unknown";
}

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
    throw Error(ErrorKind::InvalidInput, "unknown predictor '" + name + "' (use auto, parallelogram or midpoint)");
}

// Auto is an option, not a coder: the table holds what a file can store.
const char* connectivityCoderName(ConnectivityCoder c) {
    if (c == ConnectivityCoder::Auto) return "auto";
    const ConnectivityCoderEntry* entry = connectivityCoderOf(c);
    return entry ? entry->name : "unknown";
}

ConnectivityCoder parseConnectivityCoder(const std::string& name) {
    for (ConnectivityCoder c : {ConnectivityCoder::Auto, ConnectivityCoder::Ranks, ConnectivityCoder::Topological})
        if (name == connectivityCoderName(c)) return c;
    throw Error(ErrorKind::InvalidInput, "unknown connectivity coder '" + name + "' (use auto, ranks or topological)");
}

// Auto is an option, not a coder: the table holds what a file can store.
const char* geometryCoderName(GeometryCoder g) {
    if (g == GeometryCoder::Auto) return "auto";
    const GeometryCoderEntry* entry = geometryCoderOf(g);
    return entry ? entry->name : "unknown";
}

GeometryCoder parseGeometryCoder(const std::string& name) {
    if (name == geometryCoderName(GeometryCoder::Auto)) return GeometryCoder::Auto;
    if (const GeometryCoderEntry* entry = geometryCoderByName(name)) return entry->id;
    // "auto, tree, refine, sorted or raw": auto, then the table's names in its listing order.
    const std::vector<const GeometryCoderEntry*>& coders = geometryCoders();
    std::string names = std::string(geometryCoderName(GeometryCoder::Auto)) + ", ";
    for (size_t i = 0; i < coders.size(); ++i)
        names += std::string(i == 0 ? "" : (i + 1 == coders.size() ? " or " : ", ")) + coders[i]->name;
    throw Error(ErrorKind::InvalidInput, "unknown geometry coder '" + name + "' (use " + names + ")");
}

Levers parseLevers(const std::string& list) {
    if (list == "all") return Levers();
    Levers levers = Levers::none();
    if (list == "none") return levers;
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, comma - start);
        if (name == leverName(0)) levers.topologicalFilter = true;
        else if (name == leverName(1)) levers.gapClosing = true;
        else if (name == leverName(2)) levers.confidenceContext = true;
        else if (name == leverName(3)) levers.angleOrder = true;
        else if (name == leverName(4)) levers.frontNeighbours = true;
        else if (name == leverName(5)) levers.boundaryFlag = true;
        else {
            std::string names;  // "filter, gap, context, angle, front, boundary"
            for (int l = 0; l < kLeverCount; ++l) names += std::string(l == 0 ? "" : ", ") + leverName(l);
            throw Error(ErrorKind::InvalidInput, "unknown lever '" + name + "' (use all, none, or a list of " + names + ")");
        }
        start = comma + 1;
    }
    return levers;
}

std::string leversName(const Levers& l) {
    if (l.topologicalFilter && l.gapClosing && l.confidenceContext && l.angleOrder && l.frontNeighbours && l.boundaryFlag)
        return "all";
    std::string names;
    auto add = [&](bool on, const char* name) {
        if (on) names += (names.empty() ? "" : ",") + std::string(name);
    };
    add(l.topologicalFilter, leverName(0));
    add(l.gapClosing, leverName(1));
    add(l.confidenceContext, leverName(2));
    add(l.angleOrder, leverName(3));
    add(l.frontNeighbours, leverName(4));
    add(l.boundaryFlag, leverName(5));
    return names.empty() ? "none" : names;
}

namespace {
double perVertex(uint64_t bytes, uint64_t vertices) { return vertices ? 8.0 * double(bytes) / double(vertices) : 0.0; }
}  // namespace

double Stats::connectivityBitsPerVertex() const { return perVertex(connectivityBytes, vertices); }
double Stats::geometryBitsPerVertex() const { return perVertex(geometryBytes, vertices); }
double Stats::totalBitsPerVertex() const { return perVertex(totalBytes, vertices); }

std::string describeRepairs(const Stats& stats) {
    std::string out;
    auto add = [&out](uint64_t count, const char* one, const char* many) {
        if (count == 0) return;
        out += (out.empty() ? "" : ", ") + std::to_string(count) + " " + (count == 1 ? one : many);
    };
    add(stats.splitVertices, "vertex copy", "vertex copies");
    add(stats.flippedFaces, "face turned over", "faces turned over");
    add(stats.repeatedFaces, "face repeating another", "faces repeating others");
    add(stats.looseFaces, "face repeating a vertex", "faces repeating a vertex");
    if (out.empty()) return out;
    return out + " (" + std::to_string(stats.repairBytes) + " bytes)";
}

}  // namespace drm
