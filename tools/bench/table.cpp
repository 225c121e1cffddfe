#include "table.h"

#include <algorithm>
#include <sstream>

namespace drm {
namespace peers {

std::string toText(const Table& table) {
    std::vector<size_t> width;
    for (const std::string& title : table.titles) width.push_back(title.size());
    for (const auto& row : table.rows)
        for (size_t c = 0; c < row.size() && c < width.size(); ++c) width[c] = std::max(width[c], row[c].size());
    std::ostringstream out;
    auto line = [&](const std::vector<std::string>& cells) {
        std::string text;
        for (size_t c = 0; c < cells.size() && c < width.size(); ++c) {
            const std::string pad(width[c] - cells[c].size(), ' ');
            if (c > 0) text += "  ";
            text += table.numeric[c] ? pad + cells[c] : cells[c] + pad;
        }
        text.erase(text.find_last_not_of(' ') + 1);
        out << text << "\n";
    };
    line(table.titles);
    for (const auto& row : table.rows) line(row);
    return out.str();
}

std::string toMarkdown(const Table& table) {
    std::ostringstream out;
    auto line = [&](const std::vector<std::string>& cells) {
        out << "|";
        for (const std::string& cell : cells) {
            std::string escaped;
            for (char c : cell) escaped += (c == '|') ? std::string("\\|") : std::string(1, c);
            out << " " << escaped << " |";
        }
        out << "\n";
    };
    line(table.titles);
    out << "|";
    for (bool isNumeric : table.numeric) out << (isNumeric ? "---:|" : "---|");
    out << "\n";
    for (const auto& row : table.rows) line(row);
    return out.str();
}

std::string toCsv(const Table& table) {
    auto field = [](const std::string& text) {
        if (text == "-") return std::string();
        if (text.find_first_of(",\"\n") == std::string::npos) return text;
        std::string quoted = "\"";
        for (char c : text) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
        return quoted + "\"";
    };
    std::ostringstream out;
    auto line = [&](const std::vector<std::string>& cells) {
        for (size_t c = 0; c < cells.size(); ++c) out << (c ? "," : "") << field(cells[c]);
        out << "\n";
    };
    line(table.titles);
    for (const auto& row : table.rows) line(row);
    return out.str();
}

}  // namespace peers
}  // namespace drm
