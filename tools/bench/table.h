// A table of strings rendered for the terminal, Markdown or CSV.
#ifndef DRM_TOOLS_BENCH_TABLE_H
#define DRM_TOOLS_BENCH_TABLE_H

#include <string>
#include <vector>

namespace drm {
namespace peers {

struct Table {
    std::vector<std::string> titles;
    std::vector<bool> numeric;  // per column: right-aligned
    std::vector<std::vector<std::string>> rows;

    void addColumn(const std::string& title, bool isNumeric) {
        titles.push_back(title);
        numeric.push_back(isNumeric);
    }
};

std::string toText(const Table& table);      // aligned columns, two spaces apart
std::string toMarkdown(const Table& table);  // '|' in cells escaped
std::string toCsv(const Table& table);       // RFC 4180 quoting; "-" cells left empty

}  // namespace peers
}  // namespace drm

#endif  // DRM_TOOLS_BENCH_TABLE_H
