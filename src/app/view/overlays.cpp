#include "view/overlays.hpp"

#include <algorithm>

#include "view/word_wrap.hpp"

namespace psb::app {

std::vector<std::string> wrapLines(const TextMeasure& font, const std::vector<std::string>& lines,
                                   int maxWidth) {
    const float room = static_cast<float>(maxWidth - 8);  // textBoxSize's padding
    const MeasureText measure = [&font](std::string_view t) {
        return static_cast<float>(font.measure(t));
    };
    std::vector<std::string> out;
    for (const std::string& line : lines) {
        for (std::string& part : wrapAtSpaces(line, room, measure, "  "))
            out.push_back(std::move(part));
    }
    return out;
}

bool hudIsNarrow(const TextMeasure& font, int room) {
    // wrapHudLines' room: the frame's, less the padding.
    return font.measure("Kinetic energy 123 J | momentum (-0.123, -0.123) kg m/s") > room - 16;
}

std::vector<std::string> wrapHudLines(const TextMeasure& font,
                                      const std::vector<std::string>& lines, int maxWidth) {
    const int room = maxWidth - 8;  // textBoxSize's padding
    static constexpr std::string_view kBar = " | ";
    std::vector<std::string> out;
    for (const std::string& line : lines) {
        if (font.measure(line) <= room) {
            out.push_back(line);
            continue;
        }
        std::vector<std::string> packed;
        std::string current;
        for (std::size_t at = 0; at <= line.size();) {
            const std::size_t bar = std::min(line.find(kBar, at), line.size());
            const std::string part = line.substr(at, bar - at);
            if (current.empty()) {
                current = packed.empty() ? part : "  " + part;
            } else if (font.measure(current + std::string(kBar) + part) <= room) {
                current += std::string(kBar) + part;
            } else {
                packed.push_back(current);
                current = "  " + part;
            }
            at = bar + kBar.size();
        }
        packed.push_back(current);
        for (const std::string& l : wrapLines(font, packed, maxWidth))
            out.push_back(l);
    }
    return out;
}

PixelPoint textBoxSize(const TextMeasure& font, const std::vector<std::string>& lines) {
    if (lines.empty()) return {0, 0};
    int w = 0;
    for (const auto& l : lines)
        w = std::max(w, font.measure(l));
    return {w + 8, font.lineHeight() * static_cast<int>(lines.size()) + 4};
}

namespace {

/// `text` without its last aside in brackets ("... 980x1000 (25 frames a second of 60: the
/// window drew no faster)" without the brackets' words), and the space and the comma, colon or
/// semicolon before it; `text` itself where it does not end in one.
std::string withoutLastAside(const std::string& text) {
    if (text.empty() || text.back() != ')') return text;
    int depth = 0;
    for (std::size_t k = text.size(); k-- > 0;) {
        if (text[k] == ')') ++depth;
        if (text[k] == '(' && --depth == 0) {
            std::string head = text.substr(0, k);
            while (!head.empty() && (head.back() == ' ' || head.back() == ',' ||
                                     head.back() == ';' || head.back() == ':')) {
                head.pop_back();
            }
            return head.empty() ? text : head;
        }
    }
    return text;
}

}  // namespace

std::vector<std::string> messageLines(const TextMeasure& font,
                                      const std::vector<std::string>& messages, int maxWidth,
                                      std::size_t maxLines) {
    std::vector<std::string> out;
    for (auto m = messages.rbegin(); m != messages.rend(); ++m) {
        std::vector<std::string> lines = wrapLines(font, {*m}, maxWidth);
        if (out.size() + lines.size() <= maxLines) {
            out.insert(out.begin(), lines.begin(), lines.end());
            continue;
        }
        if (out.empty() && maxLines > 0) {  // the newest alone is longer than the band
            // Its asides in brackets go first, from the last: what it did and where stays
            // whole, and the band ends where the sentence does (the log has the whole).
            for (std::string text = *m, shorter = withoutLastAside(text);
                 lines.size() > maxLines && shorter != text;
                 text = shorter, shorter = withoutLastAside(text)) {
                lines = wrapLines(font, {shorter}, maxWidth);
            }
            if (lines.size() > maxLines) {
                // Still too long: its first lines, the last cut at a space where "…" fits.
                lines.resize(maxLines);
                std::string& last = lines.back();
                const std::string ellipsis = "\u2026";
                while (!last.empty() && font.measure(last + ellipsis) + 8 > maxWidth) {
                    const std::size_t space = last.find_last_of(' ');
                    if (space == std::string::npos || space == 0) {
                        // One word: whole characters off its end.
                        last.pop_back();
                        while (!last.empty() &&
                               (static_cast<unsigned char>(last.back()) & 0xC0) == 0x80)
                            last.pop_back();
                        if (!last.empty() && (static_cast<unsigned char>(last.back()) & 0x80) != 0)
                            last.pop_back();  // the lead byte of the character cut
                    } else {
                        last.resize(space);
                    }
                }
                last += ellipsis;
            }
            out = std::move(lines);
        }
        break;
    }
    return out;
}

PixelRect helpRoom(int width, int height) {
    return {kPanelMargin, kPanelMargin, std::max(0, width - 2 * kPanelMargin),
            std::max(0, height - 2 * kPanelMargin)};
}

std::vector<PixelRect> helpLineRects(const TextMeasure& font, const std::vector<std::string>& lines,
                                     PixelPoint at) {
    std::vector<PixelRect> out;
    const int lh = font.lineHeight();
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const int w = font.measure(lines[k]);
        if (w > 0) out.push_back({at.x + 4, at.y + 2 + lh * static_cast<int>(k), w, lh});
    }
    return out;
}

std::vector<std::vector<std::string>> helpPages(const TextMeasure& font,
                                                const std::vector<std::string>& lines,
                                                PixelPoint room) {
    if (lines.size() < 2) return {lines};
    const int lh = std::max(1, font.lineHeight());
    const MeasureText measure = [&font](std::string_view t) {
        return static_cast<float>(font.measure(t));
    };
    // The title and a blank line head every page.
    const std::size_t capacity = static_cast<std::size_t>(std::max(1, (room.y - 4) / lh - 2));
    std::vector<std::vector<std::string>> bodies{{}};
    for (std::size_t k = 2; k < lines.size(); ++k) {
        // A control's words continue under their own column, not under the keys.
        const std::string& line = lines[k];
        const std::size_t gap = line.find("   ");
        const std::size_t column = gap == std::string::npos ? 0 : line.find_first_not_of(' ', gap);
        // Where that column would leave its words too little room, the words go on the lines
        // under the keys instead, indented.
        const float width = static_cast<float>(room.x - 8);  // textBoxSize's padding
        const bool besideKeys =
            column == std::string::npos ||
            static_cast<float>(font.measure(std::string(column, ' '))) < width * 2 / 3;
        std::vector<std::string> wrapped;
        if (besideKeys) {
            wrapped = wrapAtSpaces(line, width, measure,
                                   std::string(column == std::string::npos ? 2 : column, ' '));
        } else {
            wrapped = wrapAtSpaces(line.substr(0, gap), width, measure, "  ");
            const std::vector<std::string> words =
                wrapAtSpaces("  " + line.substr(column), width, measure, "  ");
            wrapped.insert(wrapped.end(), words.begin(), words.end());
        }
        if (!bodies.back().empty() && bodies.back().size() + wrapped.size() > capacity)
            bodies.emplace_back();
        bodies.back().insert(bodies.back().end(), wrapped.begin(), wrapped.end());
    }
    std::vector<std::vector<std::string>> pages;
    for (std::size_t p = 0; p < bodies.size(); ++p) {
        std::string title = lines[0];
        if (bodies.size() > 1) {
            title += " (page " + std::to_string(p + 1) + " of " + std::to_string(bodies.size()) +
                     (p + 1 < bodies.size() ? ": H for the next)" : ": H closes)");
        }
        std::vector<std::string> page = wrapLines(font, {title}, room.x);
        page.push_back(lines[1]);
        page.insert(page.end(), bodies[p].begin(), bodies[p].end());
        pages.push_back(std::move(page));
    }
    return pages;
}

}  // namespace psb::app
