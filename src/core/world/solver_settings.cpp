#include <array>
#include <utility>

#include <particle_sandbox/solver_settings.hpp>

namespace psb {
namespace {

constexpr std::array<std::pair<StepMode, std::string_view>, 3> kModes{{
    {StepMode::Discrete, "discrete"},
    {StepMode::Substep, "substep"},
    {StepMode::Exact, "exact"},
}};

constexpr std::array<std::pair<BroadPhaseKind, std::string_view>, 4> kBroadPhases{{
    {BroadPhaseKind::Auto, "auto"},
    {BroadPhaseKind::AllPairs, "all-pairs"},
    {BroadPhaseKind::Grid, "grid"},
    {BroadPhaseKind::Quadtree, "quadtree"},
}};

template <typename Table, typename Key>
std::string_view nameOf(const Table& table, Key key) {
    for (const auto& [k, name] : table)
        if (k == key) return name;
    return "?";
}

template <typename Table>
auto parse(const Table& table, std::string_view name)
    -> std::optional<typename Table::value_type::first_type> {
    for (const auto& [k, n] : table)
        if (n == name) return k;
    return std::nullopt;
}

}  // namespace

std::string_view toString(StepMode mode) {
    return nameOf(kModes, mode);
}
std::string_view toString(BroadPhaseKind kind) {
    return nameOf(kBroadPhases, kind);
}
std::optional<StepMode> parseStepMode(std::string_view name) {
    return parse(kModes, name);
}
std::optional<BroadPhaseKind> parseBroadPhase(std::string_view name) {
    return parse(kBroadPhases, name);
}

}  // namespace psb
