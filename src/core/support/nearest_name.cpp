#include <particle_sandbox/detail/nearest_name.hpp>

#include <algorithm>
#include <vector>

namespace psb::detail {

std::size_t editDistance(std::string_view a, std::string_view b) {
    // Two rows of the dynamic-programming table; names here are short.
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitute = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, substitute});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::string_view nearestName(std::string_view got, std::span<const std::string_view> known) {
    std::string_view best;
    std::size_t bestDistance = SIZE_MAX;
    // Compare at most a name's worth of letters: a 10 MB key must not cost 10 MB × names.
    const std::string_view probe = got.substr(0, 64);
    for (const std::string_view name : known) {
        const std::size_t d = editDistance(probe, name);
        if (d < bestDistance) {
            bestDistance = d;
            best = name;
        }
    }
    const std::size_t allowed = std::max<std::size_t>(1, std::max(probe.size(), best.size()) / 3);
    if (got.size() <= 64 && bestDistance <= allowed) return best;
    return {};
}

std::string suggestion(std::string_view got, std::initializer_list<std::string_view> known) {
    const std::string_view best =
        nearestName(got, std::span<const std::string_view>(known.begin(), known.size()));
    if (!best.empty()) return " (did you mean '" + std::string(best) + "'?)";
    std::string list = " (expected one of: ";
    bool first = true;
    for (const std::string_view name : known) {
        if (!first) list += ", ";
        list += name;
        first = false;
    }
    return list + ")";
}

}  // namespace psb::detail
