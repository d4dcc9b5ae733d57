#include "render/trails.hpp"

#include <algorithm>
#include <climits>
#include <cmath>

namespace psb::app {

void Trails::reset() {
    std::fill(count_.begin(), count_.end(), std::uint8_t{0});
    std::fill(head_.begin(), head_.end(), std::uint8_t{0});
    followedHead_ = 0;
    followedCount_ = 0;
    lastTime_ = -1.0;
    frames_ = 0;
}

void Trails::follow(ParticleId id) {
    if (id == followed_) return;
    followed_ = id;
    followedHead_ = 0;
    followedCount_ = 0;
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
    if (const auto i = world.indexOf(followed_)) {
        followedXs_.resize(kFollowedLength);
        followedYs_.resize(kFollowedLength);
        followedXs_[followedHead_] = static_cast<float>(p.x[*i]);
        followedYs_[followedHead_] = static_cast<float>(p.y[*i]);
        followedHead_ = (followedHead_ + 1) % kFollowedLength;
        followedCount_ = std::min<std::size_t>(followedCount_ + 1, kFollowedLength);
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

void TrailImage::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = std::max(width, 0);
    height_ = std::max(height, 0);
    pixels_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0u);
    minX_ = minY_ = INT_MAX;
    maxX_ = maxY_ = -1;
}

void TrailImage::clear() {
    for (int y = minY_; y <= maxY_; ++y) {
        std::uint32_t* row = pixels_.data() + static_cast<std::size_t>(y) * width_;
        std::fill(row + minX_, row + maxX_ + 1, 0u);
    }
    minX_ = minY_ = INT_MAX;
    maxX_ = maxY_ = -1;
}

SDL_Rect TrailImage::dirty() const {
    if (maxX_ < 0) return {};
    return {minX_, minY_, maxX_ - minX_ + 1, maxY_ - minY_ + 1};
}

void TrailImage::disc(float cx, float cy, float r, std::uint32_t argb) {
    if (r < 1.0f && cx >= 1.0f && cy >= 1.0f && cx < static_cast<float>(width_ - 1) &&
        cy < static_cast<float>(height_ - 1)) {
        // A disc under a pixel's radius (the common case in dense scenes): the pixel under the
        // centre and those of its eight neighbours within r + 0.5 of the centre, without the
        // general bounding-box loop.
        const int ix = static_cast<int>(cx), iy = static_cast<int>(cy);
        const float fx = cx - static_cast<float>(ix) - 0.5f;
        const float fy = cy - static_cast<float>(iy) - 0.5f;
        const float reach2 = (r + 0.5f) * (r + 0.5f);
        std::uint32_t* centre = pixels_.data() + static_cast<std::size_t>(iy) * width_ + ix;
        for (int j = -1; j <= 1; ++j) {
            const float dy = static_cast<float>(j) - fy;
            std::uint32_t* row = centre + static_cast<std::ptrdiff_t>(j) * width_;
            for (int i = -1; i <= 1; ++i) {
                const float dx = static_cast<float>(i) - fx;
                if (dx * dx + dy * dy <= reach2 || (i == 0 && j == 0)) row[i] = argb;
            }
        }
        minX_ = std::min(minX_, ix - 1);
        minY_ = std::min(minY_, iy - 1);
        maxX_ = std::max(maxX_, ix + 1);
        maxY_ = std::max(maxY_, iy + 1);
        return;
    }
    const float reach = r + 0.5f;
    const int x0 = std::max(0, static_cast<int>(std::floor(cx - reach)));
    const int x1 = std::min(width_ - 1, static_cast<int>(std::floor(cx + reach)));
    const int y0 = std::max(0, static_cast<int>(std::floor(cy - reach)));
    const int y1 = std::min(height_ - 1, static_cast<int>(std::floor(cy + reach)));
    if (x0 > x1 || y0 > y1) return;
    const int ix = static_cast<int>(std::floor(cx)), iy = static_cast<int>(std::floor(cy));
    for (int y = y0; y <= y1; ++y) {
        const float dy = static_cast<float>(y) + 0.5f - cy;
        std::uint32_t* row = pixels_.data() + static_cast<std::size_t>(y) * width_;
        for (int x = x0; x <= x1; ++x) {
            const float dx = static_cast<float>(x) + 0.5f - cx;
            if (dx * dx + dy * dy <= reach * reach || (x == ix && y == iy)) row[x] = argb;
        }
    }
    minX_ = std::min(minX_, x0);
    minY_ = std::min(minY_, y0);
    maxX_ = std::max(maxX_, x1);
    maxY_ = std::max(maxY_, y1);
}

void TrailImage::line(float x0, float y0, float x1, float y1, std::uint32_t argb) {
    const float xmax = static_cast<float>(width_) - 0.5f;
    const float ymax = static_cast<float>(height_) - 0.5f;
    const auto inside = [&](float x, float y) {
        return x >= 0.0f && x <= xmax && y >= 0.0f && y <= ymax;
    };
    float dx = x1 - x0, dy = y1 - y0;
    if (!inside(x0, y0) || !inside(x1, y1)) {
        // Liang-Barsky: clip to the image so a trail far off screen costs nothing.
        float t0 = 0.0f, t1 = 1.0f;
        const float p[4] = {-dx, dx, -dy, dy};
        const float q[4] = {x0, xmax - x0, y0, ymax - y0};
        for (int k = 0; k < 4; ++k) {
            if (p[k] == 0.0f) {
                if (q[k] < 0.0f) return;
                continue;
            }
            const float r = q[k] / p[k];
            if (p[k] < 0.0f) {
                if (r > t1) return;
                t0 = std::max(t0, r);
            } else {
                if (r < t0) return;
                t1 = std::min(t1, r);
            }
        }
        x1 = x0 + t1 * dx;
        y1 = y0 + t1 * dy;
        x0 += t0 * dx;
        y0 += t0 * dy;
        dx = x1 - x0;
        dy = y1 - y0;
    }
    // A DDA along the major axis, one pixel per step, both end pixels included.
    const int steps = static_cast<int>(std::max(std::abs(dx), std::abs(dy))) + 1;
    const float sx = dx / static_cast<float>(steps), sy = dy / static_cast<float>(steps);
    float x = x0, y = y0;
    for (int k = 0; k <= steps; ++k, x += sx, y += sy) {
        const int ix = std::min(static_cast<int>(x), width_ - 1);
        const int iy = std::min(static_cast<int>(y), height_ - 1);
        std::uint32_t& px = pixels_[static_cast<std::size_t>(iy) * width_ + ix];
        if ((argb >> 24) > (px >> 24)) px = argb;  // the newer (more opaque) trail wins
    }
    minX_ = std::min(minX_, static_cast<int>(std::min(x0, x1)));
    minY_ = std::min(minY_, static_cast<int>(std::min(y0, y1)));
    maxX_ = std::max(maxX_, std::min(static_cast<int>(std::max(x0, x1)), width_ - 1));
    maxY_ = std::max(maxY_, std::min(static_cast<int>(std::max(y0, y1)), height_ - 1));
}

void Trails::rasteriseOne(const World& world, const Camera& camera, std::size_t index) {
    const ParticleArrays& p = world.particles();
    const ParticleId id = p.id[index];
    if (!has(id)) return;
    const std::size_t n = count_[id.slot];
    const Color c = p.color[index];
    const std::uint32_t rgb = (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
    rasterisePath(world, camera, index, xs_.data() + static_cast<std::size_t>(id.slot) * kLength,
                  ys_.data() + static_cast<std::size_t>(id.slot) * kLength, kLength,
                  (head_[id.slot] + kLength - n) % kLength, n, rgb);
}

void Trails::rasterisePath(const World& world, const Camera& camera, std::size_t index,
                           const float* xs, const float* ys, std::size_t ringLength,
                           std::size_t oldest, std::size_t n, std::uint32_t rgb, float tailAlpha,
                           bool bold) {
    const ParticleArrays& p = world.particles();
    // The camera's mapping in floats: a trail is only drawn.
    const Camera::Transform t = camera.transform();
    const float zoom = t.scale, ox = t.originX, oy = t.originY;
    float ax = ox + zoom * xs[oldest], ay = oy + zoom * ys[oldest];
    // In a periodic box a step across more than half the box is a wrap through an edge: no line
    // across the box, the trail goes on from the other side.
    const bool periodic = world.def().periodic;
    const float wrapX = 0.5f * zoom * static_cast<float>(world.def().width);
    const float wrapY = 0.5f * zoom * static_cast<float>(world.def().height);
    // Points 0..n-1 are the ring, oldest first; point n is the particle now.
    for (std::size_t k = 1; k <= n; ++k) {
        const std::size_t at = (oldest + k) % ringLength;
        const float bx = k < n ? ox + zoom * xs[at] : ox + zoom * static_cast<float>(p.x[index]);
        const float by = k < n ? oy + zoom * ys[at] : oy + zoom * static_cast<float>(p.y[index]);
        const float dx = bx - ax, dy = by - ay;
        // Steps shorter than kMinSegment px join the next one: a slow particle's trail is not
        // redrawn pixel by pixel.
        if (k < n && dx * dx + dy * dy < kMinSegment * kMinSegment) continue;
        const float f =
            tailAlpha + (1.0f - tailAlpha) * static_cast<float>(k) / static_cast<float>(n);
        const std::uint32_t argb = (static_cast<std::uint32_t>(255.0f * f) << 24) | rgb;
        if (periodic && (std::abs(dx) > wrapX || std::abs(dy) > wrapY)) {
            ax = bx;
            ay = by;
            continue;
        }
        image_.line(ax, ay, bx, by, argb);
        if (bold) {
            // The same line one pixel right and one down: two pixels wide in any direction.
            image_.line(ax + 1.0f, ay, bx + 1.0f, by, argb);
            image_.line(ax, ay + 1.0f, bx, by + 1.0f, argb);
        }
        ax = bx;
        ay = by;
    }
}

const TrailImage& Trails::rasterise(const World& world, const Camera& camera, TrailMode mode,
                                    ParticleId selected, std::size_t* drawn) {
    image_.resize(camera.viewportWidth(), camera.viewportHeight());
    image_.clear();
    std::size_t count = 0;
    if (mode == TrailMode::Selected) {
        const auto i = world.indexOf(selected);
        if (i && selected == followed_ && followedCount_ > 0) {
            // Drawn over the discs (Renderer), bold and in the selection ring's yellow, so that
            // it shows over the crowd and over its own disc.
            rasterisePath(world, camera, *i, followedXs_.data(), followedYs_.data(),
                          kFollowedLength,
                          (followedHead_ + kFollowedLength - followedCount_) % kFollowedLength,
                          followedCount_, 0xffe65au, kFollowedTailAlpha, true);
            count = 1;
        } else if (i && has(selected)) {
            rasteriseOne(world, camera, *i);
            count = 1;
        }
    } else if (mode == TrailMode::All) {
        const ParticleArrays& p = world.particles();
        for (std::size_t i = 0; i < p.size(); ++i) {
            // Rows are in id order, particles in space order: fetch a row a few trails ahead.
            if (i + 8 < p.size() && p.id[i + 8].slot < generation_.size()) {
                const std::size_t row = static_cast<std::size_t>(p.id[i + 8].slot) * kLength;
                __builtin_prefetch(xs_.data() + row);
                __builtin_prefetch(xs_.data() + row + 16);
                __builtin_prefetch(ys_.data() + row);
                __builtin_prefetch(ys_.data() + row + 16);
            }
            if (!has(p.id[i])) continue;
            rasteriseOne(world, camera, i);
            ++count;
        }
    }
    if (drawn != nullptr) *drawn = count;
    return image_;
}

}  // namespace psb::app
