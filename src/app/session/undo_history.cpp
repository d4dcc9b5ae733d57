#include "session/undo_history.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace psb::app {

namespace {

bool continuous(const std::string& label) {
    return label.rfind("set ", 0) == 0;
}

}  // namespace

UndoHistory::UndoHistory(const UndoSettings& settings) : settings_(settings) {
    if (settings_.maxEntries == 0) throw std::invalid_argument("UndoHistory: maxEntries is 0");
    if (!(settings_.coalesceSeconds >= 0.0)) {
        throw std::invalid_argument("UndoHistory: coalesceSeconds must be >= 0");
    }
}

UndoHistory::Entry UndoHistory::makeEntry(std::string label, double time, UndoState state) {
    state.world.dropEventState();
    Entry e{std::move(label), std::move(state), time, 0};
    e.bytes = sizeof(Entry) + e.state.world.stateBytes() + e.label.capacity() +
              e.state.meta.name.capacity() + e.state.meta.description.capacity();
    return e;
}

bool UndoHistory::coalesces(const std::string& label, double now) const {
    if (!mayCoalesce_ || undo_.empty() || !continuous(label)) return false;
    const Entry& newest = undo_.back();
    return newest.label == label && now >= newest.time &&
           now - newest.time <= settings_.coalesceSeconds;
}

void UndoHistory::record(const std::string& label, double now, UndoState before) {
    for (const Entry& e : redo_)
        entryBytes_ -= e.bytes;
    redo_.clear();
    if (coalesces(label, now)) {
        undo_.back().time = now;
        return;
    }
    undo_.push_back(makeEntry(label, now, std::move(before)));
    entryBytes_ += undo_.back().bytes;
    mayCoalesce_ = true;
    trim();
}

std::optional<UndoHistory::Step> UndoHistory::move(std::deque<Entry>& from, std::deque<Entry>& to,
                                                   UndoState current) {
    if (from.empty()) return std::nullopt;
    Entry e = std::move(from.back());
    from.pop_back();
    entryBytes_ -= e.bytes;
    to.push_back(makeEntry(e.label, e.time, std::move(current)));
    entryBytes_ += to.back().bytes;
    mayCoalesce_ = false;
    trim();
    return Step{std::move(e.label), std::move(e.state)};
}

std::optional<UndoHistory::Step> UndoHistory::undo(UndoState current) {
    return move(undo_, redo_, std::move(current));
}

std::optional<UndoHistory::Step> UndoHistory::redo(UndoState current) {
    return move(redo_, undo_, std::move(current));
}

std::string UndoHistory::undoLabel() const {
    return undo_.empty() ? std::string() : undo_.back().label;
}

std::string UndoHistory::redoLabel() const {
    return redo_.empty() ? std::string() : redo_.back().label;
}

std::size_t UndoHistory::memoryBytes() const {
    std::size_t bytes = entryBytes_;
    std::vector<const World*> scenes;
    const auto count = [&](const std::deque<Entry>& side) {
        for (const Entry& e : side) {
            const World* w = e.state.loaded.get();
            if (w && std::find(scenes.begin(), scenes.end(), w) == scenes.end()) {
                scenes.push_back(w);
                bytes += w->stateBytes();
            }
        }
    };
    count(undo_);
    count(redo_);
    return bytes;
}

void UndoHistory::trim() {
    while (undo_.size() + redo_.size() > 1 && (undo_.size() + redo_.size() > settings_.maxEntries ||
                                               memoryBytes() > settings_.budgetBytes)) {
        // The oldest edit goes first; the farthest redo only when it is all that is left
        // besides the newest entry.
        std::deque<Entry>& side = undo_.size() > 1 || redo_.empty() ? undo_ : redo_;
        entryBytes_ -= side.front().bytes;
        side.pop_front();
    }
}

void UndoHistory::clear() {
    undo_.clear();
    redo_.clear();
    entryBytes_ = 0;
    mayCoalesce_ = false;
}

}  // namespace psb::app
