#include "gui/panel_touch.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <imgui_internal.h>

namespace psb::app {

namespace {

/// Slower than this, window points a second, a coasting scroll stops.
constexpr float kCoastStop = 20.f;
/// A finger that rested this long before the lift flicks nothing: the scroll stops with it.
constexpr double kFlickSeconds = 0.1;

}  // namespace

void PanelTouch::down(ImVec2 at, double seconds) {
    *this = PanelTouch{};
    phase_ = Phase::Waiting;
    origin_ = last_ = at;
    downAt_ = lastAt_ = frameAt_ = seconds;
}

void PanelTouch::move(ImVec2 at, double seconds) {
    const float dy = at.y - last_.y;
    const double dt = seconds - lastAt_;
    if (phase_ == Phase::Waiting) {
        const float ax = std::abs(at.x - origin_.x), ay = std::abs(at.y - origin_.y);
        if (ay > kSlop && ay >= ax) {
            phase_ = Phase::Scrolling;
        } else if (ax > kSlop) {
            phase_ = Phase::Pressing;
        }
    }
    if (phase_ == Phase::Scrolling) {
        // The whole way from where the finger came down: the content stays under it.
        pendingScroll_ -= dy;
        if (dt > 0.0) velocity_ = 0.6f * static_cast<float>(-dy / dt) + 0.4f * velocity_;
    }
    if (phase_ == Phase::Waiting || phase_ == Phase::Pressing || phase_ == Phase::Scrolling) {
        last_ = at;
        lastAt_ = seconds;
    }
}

void PanelTouch::up(ImVec2 at, double seconds) {
    switch (phase_) {
        case Phase::Waiting:  // a tap, where the finger came down
            last_ = origin_;
            phase_ = Phase::Releasing;
            break;
        case Phase::Cancelled:
            phase_ = Phase::Lifted;
            break;
        case Phase::Pressing:
            if (at.x != last_.x || at.y != last_.y) move(at, seconds);
            phase_ = Phase::Releasing;
            break;
        case Phase::Scrolling:
            // The lift's own report at the last place is no sample of the finger's speed.
            if (at.x != last_.x || at.y != last_.y) move(at, seconds);
            if (seconds - lastAt_ > kFlickSeconds) velocity_ = 0.f;
            phase_ = Phase::Coasting;
            break;
        default:
            break;
    }
}

void PanelTouch::cancel() {
    if (phase_ == Phase::Waiting || phase_ == Phase::Pressing || phase_ == Phase::Scrolling) {
        phase_ = Phase::Cancelled;
    }
    pendingScroll_ = 0.f;
    velocity_ = 0.f;
}

void PanelTouch::sliderUnder(bool slider) {
    const bool unpressed = phase_ == Phase::Waiting || (phase_ == Phase::Releasing && !pressShown_);
    if (unpressed && hoverFrames_ > 0) overSlider_ = slider;
}

std::optional<PanelTouch::Pointer> PanelTouch::frame(double seconds) {
    const double dt = std::max(0.0, seconds - frameAt_);
    frameAt_ = seconds;
    Pointer p;
    p.scrollFrom = origin_;
    // A finger held still on a slider presses nothing: it may be about to scroll.
    if (phase_ == Phase::Waiting && seconds - downAt_ >= kHoldSeconds && !overSlider_) {
        phase_ = Phase::Pressing;
    }
    switch (phase_) {
        case Phase::None:
            return std::nullopt;
        case Phase::Waiting:  // hovered, so the control under the finger lights up
            p.at = origin_;
            ++hoverFrames_;
            return p;
        case Phase::Pressing:
            // The press lands where the finger came down, then follows it.
            p.at = pressShown_ ? last_ : origin_;
            p.down = true;
            pressShown_ = true;
            return p;
        case Phase::Scrolling:
            p.scroll = std::exchange(pendingScroll_, 0.f);
            return p;
        case Phase::Releasing:
            if (!pressShown_ && hoverFrames_ == 0) {  // what is under the tap, first
                p.at = origin_;
                ++hoverFrames_;
                return p;
            }
            if (!pressShown_ && overSlider_) {  // a tap on a slider: its value stays
                phase_ = Phase::None;
                return p;
            }
            if (!pressShown_) {  // lifted before any frame saw the press: one frame down first
                p.at = origin_;
                p.down = true;
                pressShown_ = true;
            } else {
                p.at = last_;
                phase_ = Phase::Lifted;
            }
            return p;
        case Phase::Coasting:
            p.scroll = std::exchange(pendingScroll_, 0.f) + velocity_ * static_cast<float>(dt);
            velocity_ *= static_cast<float>(std::exp(-dt / kCoastSeconds));
            if (std::abs(velocity_) < kCoastStop) phase_ = Phase::Lifted;
            return p;
        case Phase::Cancelled:  // no pointer: nothing hovered, pressed or scrolled
            return p;
        case Phase::Lifted:  // one frame with no pointer, so that ImGui lets go of the hover
            phase_ = Phase::None;
            return p;
    }
    return std::nullopt;
}

void scrollWindowAt(ImVec2 at, float by, float scale) {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    const ImVec2 p(at.x / scale, at.y / scale);
    by /= scale;
    ImGuiWindow* w = nullptr;
    // The frontmost window there: later in the list is drawn over earlier.
    for (int k = g.Windows.Size - 1; k >= 0 && w == nullptr; --k) {
        ImGuiWindow* c = g.Windows[k];
        if (!c->Active || c->Hidden || (c->Flags & ImGuiWindowFlags_NoMouseInputs) != 0) continue;
        if (c->OuterRectClipped.Contains(p)) w = c;
    }
    for (; w != nullptr; w = w->ParentWindow) {
        const float room = by > 0.f ? w->ScrollMax.y - w->Scroll.y : w->Scroll.y;
        if (room > 0.5f) {
            ImGui::SetScrollY(w, std::clamp(w->Scroll.y + by, 0.f, w->ScrollMax.y));
            return;
        }
        if ((w->Flags & ImGuiWindowFlags_ChildWindow) == 0) return;
    }
}

}  // namespace psb::app
