#include "view/soft_wrap.hpp"

#include <algorithm>
#include <string_view>

namespace psb::app {

std::string SoftWrap::start(const std::string& text, float room, const MeasureText& measure) {
    shown_ = text;
    soft_.assign(shown_.size(), false);
    wrap(room, measure);
    return shown_;
}

bool SoftWrap::edited(std::string& shown, float room, const MeasureText& measure) {
    // What the change left alone: the longest common start and end of the text before and after.
    const std::size_t before = shown_.size(), after = shown.size();
    std::size_t head = 0;
    while (head < before && head < after && shown_[head] == shown[head])
        ++head;
    std::size_t tail = 0;
    while (tail < before - head && tail < after - head &&
           shown_[before - 1 - tail] == shown[after - 1 - tail]) {
        ++tail;
    }
    std::vector<bool> soft(after, false);
    std::copy(soft_.begin(), soft_.begin() + static_cast<std::ptrdiff_t>(head), soft.begin());
    std::copy(soft_.end() - static_cast<std::ptrdiff_t>(tail), soft_.end(),
              soft.end() - static_cast<std::ptrdiff_t>(tail));
    shown_ = shown;
    for (std::size_t i = 0; i < after; ++i)
        if (soft[i]) shown_[i] = ' ';
    soft_.assign(after, false);
    wrap(room, measure);
    if (shown_ == shown) return false;
    shown = shown_;
    return true;
}

std::string SoftWrap::text(const std::string& shown) const {
    std::string out = shown;
    for (std::size_t i = 0; i < out.size() && i < soft_.size(); ++i)
        if (soft_[i] && out[i] == '\n') out[i] = ' ';
    return out;
}

void SoftWrap::wrap(float room, const MeasureText& measure) {
    // Greedy, a line at a time: a word that would end past the room goes to the next line,
    // broken at the last space before it; a word wider than the room stays whole on its own.
    const std::string_view s = shown_;
    std::size_t line = 0;  // where the current line starts
    std::size_t lastSpace = std::string_view::npos;
    std::size_t i = 0;
    while (i < s.size()) {
        if (s[i] == '\n') {  // the user's own break
            line = ++i;
            lastSpace = std::string_view::npos;
            continue;
        }
        if (s[i] == ' ') {
            lastSpace = i++;
            continue;
        }
        std::size_t end = i;
        while (end < s.size() && s[end] != ' ' && s[end] != '\n')
            ++end;
        if (measure(s.substr(line, end - line)) > room && lastSpace != std::string_view::npos &&
            lastSpace >= line) {
            shown_[lastSpace] = '\n';
            soft_[lastSpace] = true;
            line = lastSpace + 1;
            lastSpace = std::string_view::npos;
        }
        i = end;
    }
}

}  // namespace psb::app
