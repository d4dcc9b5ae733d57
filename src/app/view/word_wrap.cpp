#include "view/word_wrap.hpp"

namespace psb::app {

std::vector<std::string> wrapAtSpaces(std::string_view text, float room, const MeasureText& measure,
                                      std::string_view indent) {
    std::vector<std::string> out;
    std::size_t from = 0;
    while (true) {
        const std::size_t newline = text.find('\n', from);
        const std::string_view line =
            text.substr(from, newline == std::string_view::npos ? text.npos : newline - from);
        if (measure(line) <= room) {
            out.emplace_back(line);
        } else {
            std::string current;
            std::size_t at = 0;
            while (at < line.size()) {
                const std::size_t space = line.find(' ', at + 1);
                const std::size_t end = space == std::string_view::npos ? line.size() : space;
                const std::string_view word = line.substr(at, end - at);  // with its leading space
                if (!current.empty() && measure(std::string(current).append(word)) > room) {
                    out.push_back(current);
                    const std::size_t first = word.find_first_not_of(' ');
                    current = std::string(indent);
                    if (first != std::string_view::npos) current.append(word.substr(first));
                } else {
                    current.append(word);
                }
                at = end;
            }
            if (!current.empty()) out.push_back(current);
        }
        if (newline == std::string_view::npos) break;
        from = newline + 1;
    }
    return out;
}

}  // namespace psb::app
