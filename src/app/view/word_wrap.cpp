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
                // A path starts on this line and goes on after a separator (its folders a line
                // each): it has no space to break at, and a path put whole on a line of its own
                // left its line before half empty (a message then needed a line more than its
                // band had). A path: two separators ("/home/x", not "m/s"), or one word wider
                // than the room.
                const std::size_t separator = word.find_first_of("/\\");
                const bool path =
                    separator != std::string_view::npos &&
                    (word.find_first_of("/\\", separator + 1) != std::string_view::npos ||
                     measure(word) > room);
                if (!current.empty() && !path &&
                    measure(std::string(current).append(word)) > room) {
                    out.push_back(current);
                    const std::size_t first = word.find_first_not_of(' ');
                    current = std::string(indent);
                    if (first != std::string_view::npos) current.append(word.substr(first));
                } else {
                    current.append(word);
                }
                while (measure(current) > room) {
                    const std::size_t start = current.find_first_not_of(' ');
                    std::size_t cut = std::string::npos;
                    for (std::size_t k = current.find_first_of("/\\", start);
                         k != std::string::npos; k = current.find_first_of("/\\", k + 1)) {
                        // Never after the path's own first separator: "(folder /" left the
                        // line with a lone "/" ("(folder / / tmp/...").
                        const bool first = k == 0 || current[k - 1] == ' ' || current[k - 1] == '(';
                        if (!first && k + 1 < current.size() &&
                            measure(current.substr(0, k + 1)) <= room)
                            cut = k + 1;
                    }
                    std::size_t skip = 0;
                    if (cut == std::string::npos) {
                        // Not even the path's first folder fits after the words before it:
                        // those words keep the line.
                        const std::size_t lastSpace = current.rfind(' ');
                        if (lastSpace == std::string::npos || lastSpace <= start) break;
                        cut = lastSpace;
                        skip = 1;
                    }
                    out.push_back(current.substr(0, cut));
                    current = std::string(indent) + current.substr(cut + skip);
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
