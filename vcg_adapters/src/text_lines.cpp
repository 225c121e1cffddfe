// takeLine, stripComment, unwritableNameReason: see text_lines.h.
#include "text_lines.h"

namespace drm {
namespace vcgio {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

std::vector<std::string> splitWords(const std::string& line) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; };
    std::vector<std::string> words;
    size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && blank(line[at])) ++at;
        const size_t start = at;
        while (at < line.size() && !blank(line[at])) ++at;
        if (at > start) words.push_back(line.substr(start, at - start));
    }
    return words;
}

std::string joinList(const std::vector<std::string>& items) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += (i + 1 == items.size()) ? " and " : ", ";
        out += items[i];
    }
    return out;
}

std::string takeLine(const std::string& text, size_t& position) {
    size_t end = position;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    std::string line = text.substr(position, end - position);
    if (end < text.size() && text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n') ++end;
    position = end + 1;
    return line;
}

void stripComment(std::string& line) {
    for (size_t i = 0; i < line.size(); ++i)
        if (line[i] == '#' && (i == 0 || isBlank(line[i - 1]))) {
            line.resize(i);
            break;
        }
    size_t from = 0;
    while (from < line.size() && isBlank(line[from])) ++from;
    size_t to = line.size();
    while (to > from && isBlank(line[to - 1])) --to;
    line = line.substr(from, to - from);
}

bool holdsControlCharacter(const std::string& text) {
    for (char c : text) {
        const unsigned char u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\t') || u == 0x7F) return true;
    }
    return false;
}

const char* unwritableNameReason(const std::string& name, bool objOrMtl) {
    if (holdsControlCharacter(name)) return "it holds a line break or another control character";
    for (size_t i = 0; i < name.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(name[i]);
        if (objOrMtl && c == '#' && i > 0 && isBlank(name[i - 1])) return "it holds a '#' after a blank, where a comment starts";
    }
    if (objOrMtl && !name.empty() && (isBlank(name.front()) || isBlank(name.back()))) return "it starts or ends with a blank";
    if (objOrMtl && !name.empty() && name[0] == '#') return "it starts with '#', where a comment starts";
    return nullptr;
}

std::string printableName(const std::string& name) {
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    for (char c : name) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else if (u < 0x20 || u == 0x7F) out += std::string("\\x") + kHex[u >> 4] + kHex[u & 15];
        else out += c;
    }
    return out;
}

}  // namespace vcgio
}  // namespace drm
