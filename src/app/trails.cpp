#include "trails.hpp"

#include <algorithm>

namespace psb::app {

TrailMode nextTrailMode(TrailMode mode) {
    switch (mode) {
        case TrailMode::Off:
            return TrailMode::Selected;
        case TrailMode::Selected:
            return TrailMode::All;
        case TrailMode::All:
            break;
    }
    return TrailMode::Off;
}

const char* toString(TrailMode mode) {
    switch (mode) {
        case TrailMode::Off:
            return "off";
        case TrailMode::Selected:
            return "selected";
        case TrailMode::All:
            break;
    }
    return "all";
}

void Trails::reset() {
    std::fill(count_.begin(), count_.end(), std::uint8_t{0});
    std::fill(head_.begin(), head_.end(), std::uint8_t{0});
    lastTime_ = -1.0;
    frames_ = 0;
}

void Trails::update(const World& world) {
    if (world.time() == lastTime_) return;
    lastTime_ = world.time();
    if (frames_++ % kSampleFrames == 0) sample(world);
}

void Trails::sample(const World& world) {
    const ParticleArrays& p = world.particles();
    std::uint32_t slots = 0;
    for (const ParticleId id : p.id)
        slots = std::max(slots, id.slot + 1);
    if (slots > generation_.size()) {
        // Grows only with the world; a new row starts empty (count 0).
        xs_.resize(static_cast<std::size_t>(slots) * kLength);
        ys_.resize(static_cast<std::size_t>(slots) * kLength);
        generation_.resize(slots, UINT32_MAX);
        head_.resize(slots, 0);
        count_.resize(slots, 0);
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
        const ParticleId id = p.id[i];
        if (generation_[id.slot] != id.generation) {  // a new particle in a reused slot
            generation_[id.slot] = id.generation;
            count_[id.slot] = 0;
            head_[id.slot] = 0;
        }
        const std::size_t at = static_cast<std::size_t>(id.slot) * kLength + head_[id.slot];
        xs_[at] = static_cast<float>(p.x[i]);
        ys_[at] = static_cast<float>(p.y[i]);
        head_[id.slot] = static_cast<std::uint8_t>((head_[id.slot] + 1) % kLength);
        if (count_[id.slot] < kLength) ++count_[id.slot];
    }
}

std::size_t Trails::length(ParticleId id) const {
    return has(id) ? count_[id.slot] : 0;
}

Vec2 Trails::point(ParticleId id, std::size_t k) const {
    const std::size_t n = count_[id.slot];
    const std::size_t oldest = (head_[id.slot] + kLength - n) % kLength;
    const std::size_t at = static_cast<std::size_t>(id.slot) * kLength + (oldest + k) % kLength;
    return {xs_[at], ys_[at]};
}

void Trails::drawOne(SDL_Renderer* renderer, const World& world, const Camera& camera,
                     std::size_t index) {
    const ParticleArrays& p = world.particles();
    const ParticleId id = p.id[index];
    if (!has(id)) return;
    const std::size_t n = count_[id.slot];
    line_.clear();
    for (std::size_t k = 0; k < n; ++k) {
        const Vec2 s = camera.worldToScreen(point(id, k));
        line_.push_back({static_cast<float>(s.x()), static_cast<float>(s.y())});
    }
    const Vec2 now = camera.worldToScreen(Vec2(p.x[index], p.y[index]));
    line_.push_back({static_cast<float>(now.x()), static_cast<float>(now.y())});
    // Bands share their end points so the polyline has no gaps; the oldest band is dimmest.
    const std::size_t segments = line_.size() - 1;
    const Color c = p.color[index];
    for (int b = 0; b < kBands; ++b) {
        const std::size_t from = segments * static_cast<std::size_t>(b) / kBands;
        const std::size_t to = segments * static_cast<std::size_t>(b + 1) / kBands;
        if (to <= from) continue;
        const double f = 0.25 + 0.75 * (b + 1) / static_cast<double>(kBands);
        SDL_SetRenderDrawColor(renderer, static_cast<Uint8>(c.r * f), static_cast<Uint8>(c.g * f),
                               static_cast<Uint8>(c.b * f), 255);
        SDL_RenderDrawLinesF(renderer, line_.data() + from, static_cast<int>(to - from + 1));
    }
}

std::size_t Trails::draw(SDL_Renderer* renderer, const World& world, const Camera& camera,
                         TrailMode mode, ParticleId selected) {
    if (mode == TrailMode::Off) return 0;
    // Dimmed colours on black instead of alpha: opaque lines skip the blend per pixel.
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    std::size_t drawn = 0;
    if (mode == TrailMode::Selected) {
        if (const auto i = world.indexOf(selected)) {
            drawOne(renderer, world, camera, *i);
            drawn = has(selected) ? 1 : 0;
        }
    } else {
        const ParticleArrays& p = world.particles();
        for (std::size_t i = 0; i < p.size(); ++i) {
            if (!has(p.id[i])) continue;
            drawOne(renderer, world, camera, i);
            ++drawn;
        }
    }
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_BLEND);
    return drawn;
}

}  // namespace psb::app
