// readMtl: see mtl_library.h.
#include "mtl_library.h"

#include "text_lines.h"

#include <cstdlib>
#include <cstring>

namespace drm {
namespace vcgio {

namespace {

// Statements whose arguments are all numbers.
const char* const kNumericStatements[] = {"Ka", "Kd", "Ks", "Ke", "Tf", "Ns", "Ni", "d", "Tr", "illum", "sharpness",
                                          "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor"};
// Statements that name a texture file, after options.
const char* const kTextureStatements[] = {"map_Ka", "map_Kd", "map_Ks", "map_Ke", "map_Ns", "map_d", "map_Tr",
                                          "map_bump", "map_Bump", "bump", "disp", "decal", "refl", "norm",
                                          "map_Pr", "map_Pm", "map_Ps"};

template <size_t N>
bool oneOf(const std::string& word, const char* const (&list)[N]) {
    for (const char* item : list)
        if (word == item) return true;
    return false;
}

bool isBlank(char c) { return c == ' ' || c == '\t'; }

// Statements left out that a note names one by one.
const size_t kDroppedNamed = 5;

bool isNumber(const std::string& token) {
    char* end = nullptr;
    std::strtod(token.c_str(), &end);
    return end != token.c_str() && *end == '\0';
}

// The words of `line` with where each starts.
struct Word {
    std::string text;
    size_t start;
};
std::vector<Word> wordsOf(const std::string& line) {
    std::vector<Word> words;
    size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && isBlank(line[at])) ++at;
        const size_t start = at;
        while (at < line.size() && !isBlank(line[at])) ++at;
        if (at > start) words.push_back(Word{line.substr(start, at - start), start});
    }
    return words;
}

// How many arguments a texture option takes at most (the -o, -s and -t
// offsets take one to three numbers).
size_t optionArguments(const std::string& option) {
    if (option == "-o" || option == "-s" || option == "-t") return 3;
    if (option == "-mm") return 2;
    return 1;  // -blendu -blendv -bm -boost -cc -clamp -imfchan -texres -type
}

}  // namespace

MtlLibrary readMtl(const std::string& text) {
    MtlLibrary library;
    std::string material;
    size_t position = 0, lineNumber = 0;
    while (position < text.size()) {
        std::string line = takeLine(text, position);
        ++lineNumber;
        stripComment(line);
        if (line.empty()) continue;
        const std::vector<Word> words = wordsOf(line);
        const std::string& keyword = words[0].text;
        const auto drop = [&] {
            if (++library.droppedCount <= kDroppedNamed)
                library.dropped.push_back("line " + std::to_string(lineNumber) + " (" + keyword.substr(0, 40) + ")");
        };
        if (words.size() < 2 || holdsControlCharacter(line)) {
            drop();
            continue;
        }
        if (keyword == "newmtl") {
            material = line.substr(words[1].start);
            library.text += "newmtl " + material + "\n";
        } else if (oneOf(keyword, kNumericStatements)) {
            std::string statement = keyword;
            bool numeric = true;
            for (size_t w = 1; w < words.size(); ++w) {
                numeric = numeric && isNumber(words[w].text);
                statement += " " + words[w].text;
            }
            if (numeric) library.text += statement + "\n";
            else drop();
        } else if (oneOf(keyword, kTextureStatements)) {
            // Options first (-s 1 1 1, -clamp on, ...), then the file name,
            // which may hold blanks: the rest of the line.
            std::string statement = keyword;
            size_t w = 1;
            while (w + 1 < words.size() && words[w].text.size() > 1 && words[w].text[0] == '-' &&
                   !isNumber(words[w].text)) {
                statement += " " + words[w].text;
                const size_t most = optionArguments(words[w].text);
                ++w;
                for (size_t taken = 0; taken < most && w + 1 < words.size(); ++taken, ++w) {
                    if (taken > 0 && !isNumber(words[w].text)) break;
                    statement += " " + words[w].text;
                }
            }
            const std::string file = line.substr(words[w].start);
            library.text += statement + " " + file + "\n";
            if (keyword == "map_Kd") library.textures.emplace_back(material, file);
        } else {
            drop();
        }
    }
    return library;
}

}  // namespace vcgio
}  // namespace drm
