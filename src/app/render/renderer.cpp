#include "render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "render/obstacle_drawing.hpp"
#include "render/sdl_color.hpp"
#include "render/spin_mark.hpp"
#include "render/text.hpp"
#include "session/units.hpp"
#include "view/arrow_clip.hpp"
#include "view/label_places.hpp"
#include "view/mass_shade.hpp"
#include "view/particle_labels.hpp"

namespace psb::app {

namespace {

constexpr int kCircleTexture = 128;  // pixels; a disc bigger than this on screen is upscaled

SDL_Texture* makeCircleTexture(SDL_Renderer* renderer) {
    SDL_Surface* s = SDL_CreateRGBSurfaceWithFormat(0, kCircleTexture, kCircleTexture, 32,
                                                    SDL_PIXELFORMAT_ARGB8888);
    if (s == nullptr) return nullptr;
    // A white disc whose alpha falls off over one texel at the rim (anti-aliasing).
    const double c = kCircleTexture / 2.0, r = c - 1.0;
    auto* pixels = static_cast<Uint32*>(s->pixels);
    for (int y = 0; y < kCircleTexture; ++y) {
        for (int x = 0; x < kCircleTexture; ++x) {
            const double d = std::hypot(x + 0.5 - c, y + 0.5 - c);
            const double a = std::clamp(r - d + 0.5, 0.0, 1.0);
            pixels[y * (s->pitch / 4) + x] =
                SDL_MapRGBA(s->format, 255, 255, 255, static_cast<Uint8>(std::lround(a * 255)));
        }
    }
    SDL_Texture* t = SDL_CreateTextureFromSurface(renderer, s);
    SDL_FreeSurface(s);
    if (t != nullptr) SDL_SetTextureBlendMode(t, SDL_BLENDMODE_BLEND);
    return t;
}

std::uint32_t argb(const Color& c) {
    return 0xFF000000u | (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
}

}  // namespace

Renderer::Renderer(SDL_Renderer* renderer, const Font* labelFont)
    : renderer_(renderer), labelFont_(labelFont), circle_(makeCircleTexture(renderer)) {
    if (circle_ == nullptr) {
        throw std::runtime_error(std::string("cannot make the circle texture: ") + SDL_GetError());
    }
}

Renderer::~Renderer() {
    SDL_DestroyTexture(circle_);
    for (ImageLayer* l : {&trailLayer_, &smallLayer_}) {
        if (l->texture != nullptr) SDL_DestroyTexture(l->texture);
    }
}

void Renderer::drawImage(const TrailImage& image, ImageLayer& layer) {
    const SDL_Rect r = image.dirty();
    if (r.w <= 0 || r.h <= 0) return;
    if (layer.texture == nullptr || layer.width != image.width() ||
        layer.height != image.height()) {
        if (layer.texture != nullptr) SDL_DestroyTexture(layer.texture);
        layer.texture =
            SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STREAMING,
                              image.width(), image.height());
        if (layer.texture == nullptr) return;  // no layer rather than no frame
        SDL_SetTextureBlendMode(layer.texture, SDL_BLENDMODE_BLEND);
        layer.width = image.width();
        layer.height = image.height();
    }
    // Only the rectangle that holds pixels is uploaded and copied.
    const std::uint32_t* first =
        image.pixels() + static_cast<std::size_t>(r.y) * image.width() + r.x;
    SDL_UpdateTexture(layer.texture, &r, first, image.width() * 4);
    SDL_RenderCopy(renderer_, layer.texture, &r, &r);
}

void Renderer::drawWalls(const World& world, const Camera& camera, const Palette& colours) {
    const WorldDef& d = world.def();
    const Vec2 a = camera.worldToScreen(Vec2::Zero());
    const Vec2 b = camera.worldToScreen(Vec2(d.width, d.height));
    // The original's walls thicken with zoom; here 0.4 % of the box's smaller side, at least
    // two pixels, drawn outside the box so they never cover a particle touching them.
    const auto t = static_cast<float>(boxWallPixels(d.width, d.height, camera.zoom()));
    const float x0 = static_cast<float>(a.x()), y0 = static_cast<float>(a.y());
    const float x1 = static_cast<float>(b.x()), y1 = static_cast<float>(b.y());
    const SDL_FRect rects[4] = {{x0 - t, y0 - t, x1 - x0 + 2 * t, t},
                                {x0 - t, y1, x1 - x0 + 2 * t, t},
                                {x0 - t, y0, t, y1 - y0},
                                {x1, y0, t, y1 - y0}};
    setDrawColor(renderer_, d.walls ? colours.walls : colours.openWalls);  // open: only a hint
    SDL_RenderFillRectsF(renderer_, rects, 4);
}

void Renderer::drawDashes(const PeriodicBoxView& box, const Palette& colours) {
    // Each dash a rectangle centred on the edge's line, as long as the dash: the discs crossing
    // it are drawn over it.
    std::vector<SDL_FRect> rects;
    rects.reserve(box.dashes.size());
    const double half = 0.5 * box.thickness;
    for (const BoxDash& d : box.dashes) {
        const bool horizontal = std::abs(d.to.x() - d.from.x()) >= std::abs(d.to.y() - d.from.y());
        const double x0 = std::min(d.from.x(), d.to.x()) - (horizontal ? 0.0 : half);
        const double x1 = std::max(d.from.x(), d.to.x()) + (horizontal ? 0.0 : half);
        const double y0 = std::min(d.from.y(), d.to.y()) - (horizontal ? half : 0.0);
        const double y1 = std::max(d.from.y(), d.to.y()) + (horizontal ? half : 0.0);
        rects.push_back({static_cast<float>(x0), static_cast<float>(y0),
                         static_cast<float>(x1 - x0), static_cast<float>(y1 - y0)});
    }
    setDrawColor(renderer_, colours.walls);
    if (!rects.empty())
        SDL_RenderFillRectsF(renderer_, rects.data(), static_cast<int>(rects.size()));
}

void Renderer::drawGhost(const Camera& camera, const Vec2& centre, double radius,
                         const Palette& colours) {
    const Vec2 c = camera.worldToScreen(centre);
    const double r = std::max(1.0, camera.toScreen(radius));
    GeometryBatch ghost;
    ghost.quad(static_cast<float>(c.x() - r), static_cast<float>(c.y() - r),
               static_cast<float>(c.x() + r), static_cast<float>(c.y() + r),
               sdlColor(colours.ghost));
    ghost.draw(renderer_, circle_);
}

DrawStats Renderer::draw(const World& world, double frame, const Camera& camera,
                         const ViewOptions& options, Trails* trails, ParticleId selected,
                         const LabelKeepOut* avoid, const GeometryBatch* underlay,
                         const PeriodicBoxView* periodic) {
    const Palette& colours = palette(options.theme);
    SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_BLEND);
    setDrawColor(renderer_, colours.background);
    SDL_RenderClear(renderer_);
    if (periodic != nullptr) {
        drawDashes(*periodic, colours);
    } else {
        drawWalls(world, camera, colours);
    }
    if (!world.obstacles().empty()) {
        batchObstacles(world, camera, obstacles_, colours);
        obstacles_.draw(renderer_, circle_);
    }
    if (underlay != nullptr && !underlay->empty()) underlay->draw(renderer_, circle_);
    // Every particle's trail goes under the discs; the selected one's over them, so that the
    // gas around it cannot hide it.
    if (trails != nullptr && options.trails == TrailMode::All) {
        drawImage(trails->rasterise(world, camera, options.trails, selected), trailLayer_);
    }

    small_.resize(camera.viewportWidth(), camera.viewportHeight());
    small_.clear();
    discs_.clear();
    arrows_.clear();
    labelBoxes_.clear();
    labelText_.clear();

    const ParticleArrays& p = world.particles();
    // A particle's colour as drawn: the scene's, or on the light theme the palette's for it
    // (remembered for the last colour seen: a scene has few colours, often in runs).
    Color seen = p.size() > 0 ? p.color[0] : Color{}, drawnAs = lightColour(seen);
    const auto colourOf = [&](std::size_t i) {
        if (!colours.mapParticles) return p.color[i];
        if (!(p.color[i] == seen)) {
            seen = p.color[i];
            drawnAs = lightColour(seen);
        }
        return drawnAs;
    };
    // Its fill: that colour in the shade of its mass when the scene's masses differ
    // (view/mass_shade.hpp). A colour's shades are worked out once (shades_), and a run of
    // equal colour and mass, as scenes build them, reuses the last fill.
    const MassRange masses = massRange(p.mass);
    if (shadesTheme_ != options.theme) {
        shades_.clear();
        shadesTheme_ = options.theme;
    }
    Color shadedColour = seen;
    const MassShades* shades = nullptr;
    double lastMass = -1.0;
    Color lastFill = seen;
    const auto fillOf = [&](std::size_t i) {
        const Color c = colourOf(i);
        if (!masses.varies()) return c;
        if (shades == nullptr || !(c == shadedColour)) {
            shadedColour = c;
            const std::uint32_t key = (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
            auto it = shades_.find(key);
            if (it == shades_.end()) it = shades_.emplace(key, massShades(c, options.theme)).first;
            shades = &it->second;
            lastMass = -1.0;
        }
        if (p.mass[i] != lastMass) {
            lastMass = p.mass[i];
            lastFill = shades->at(masses.place(lastMass));
        }
        return lastFill;
    };
    const double w = camera.viewportWidth(), h = camera.viewportHeight();
    const double zoom = camera.zoom();
    DrawStats stats;
    const double spacing =
        p.size() > 0
            ? std::sqrt(world.def().width * world.def().height / static_cast<double>(p.size()))
            : world.def().width;
    const double minExtra = minArrowExtra(camera.toScreen(spacing));
    // A particle resting on the floor or a ramp in the discrete and substep modes keeps the
    // speed one step of gravity gives it (the contact takes it back the next step): at rest,
    // no arrow; its minimum arrow pointed through the floor like a leak.
    const double resting = restingSpeed(world, frame);
    // A world that keeps no rotation has no angles to show (and no arrays to read).
    const bool spin = options.spin && p.rotation;
    std::vector<std::size_t> visible;
    visible.reserve(p.size());
    arrowLength_.clear();
    visibleShift_.clear();
    // The particle `i` drawn at its centre moved by `shift` metres (an image in a periodic box).
    const auto drawDisc = [&](std::size_t i, const Vec2& shift) {
        const Vec2 s = camera.worldToScreen(Vec2(p.x[i], p.y[i]) + shift);
        // Tiny discs stay visible as about one pixel.
        const double r = std::max(0.75, camera.toScreen(p.radius[i]));
        // Arrows can reach beyond the disc, so cull with the arrow's reach when shown.
        // (sqrt rather than hypot: speeds cannot overflow a square, and hypot was a sixth of
        // the frame at 5·10⁴ particles.)
        const double speed = std::sqrt(p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
        const double len = options.arrows && speed > resting
                               ? arrowPixels(speed, options.arrowSeconds, zoom,
                                             camera.toScreen(p.radius[i]), minExtra)
                               : 0.0;
        const double reach = std::max(r, len);
        if (s.x() + reach < 0 || s.x() - reach > w || s.y() + reach < 0 || s.y() - reach > h) {
            return;
        }
        visible.push_back(i);
        arrowLength_.push_back(len);
        visibleShift_.push_back(shift);
        if (s.x() + r < 0 || s.x() - r > w || s.y() + r < 0 || s.y() - r > h) return;
        if (shift == Vec2::Zero()) ++stats.drawn;  // particles, not images
        if (r < kSmallDiscPixels) {
            small_.disc(static_cast<float>(s.x()), static_cast<float>(s.y()), static_cast<float>(r),
                        argb(fillOf(i)));
            return;
        }
        const Color drawn = fillOf(i);
        const SDL_Color c{drawn.r, drawn.g, drawn.b, 255};
        discs_.quad(static_cast<float>(s.x() - r), static_cast<float>(s.y() - r),
                    static_cast<float>(s.x() + r), static_cast<float>(s.y() + r), c);
        if (spin && r >= kSpinMarkPixels && p.fixedRotation[i] == 0) {
            addSpinMark(discs_, static_cast<float>(s.x()), static_cast<float>(s.y()),
                        static_cast<float>(r), p.angle[i], drawn);
        }
    };
    for (std::size_t i = 0; i < p.size(); ++i)
        drawDisc(i, Vec2::Zero());
    // Labels are the particles' own: the images come after them in `visible`.
    const std::size_t particlesVisible = visible.size();
    if (periodic != nullptr) {
        for (const PeriodicImage& image : periodic->images) {
            if (image.index < p.size()) drawDisc(image.index, image.offset);
        }
    }

    if (options.arrows) {
        // Arrows stay in a walled box: one that reaches past a wall ends there, cut
        // (view/arrow_clip.hpp); a periodic box's arrows run on across its edges.
        const bool walled = world.def().walls && periodic == nullptr;
        const Camera::ScreenBox inside = camera.boxOnScreen(world.def().width, world.def().height);
        for (std::size_t k = 0; k < visible.size(); ++k) {
            const std::size_t i = visible[k];
            const double r = camera.toScreen(p.radius[i]);
            const double len = arrowLength_[k];  // from the centre, pixels
            if (len <= r) continue;              // not moving: no arrow
            const double speed = std::sqrt(p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
            const Vec2 u(p.vx[i] / speed, p.vy[i] / speed);
            const Vec2 n(-u.y(), u.x());
            const Vec2 c = camera.worldToScreen(Vec2(p.x[i], p.y[i]) + visibleShift_[k]);
            const ClippedArrow clipped =
                walled ? clipArrow(c, c + len * u, inside) : ClippedArrow{c + len * u, false};
            const Vec2 tip = clipped.tip;
            if (clipped.cut && (tip - c).dot(u) <= r + 1.0) continue;  // no room past the rim
            if (std::max(0.75, r) < kSmallDiscPixels) {
                // A one-pixel shaft from the rim, and a head of two strokes when there is room;
                // cut at a wall, a bar across its end instead.
                const Vec2 start = c + r * u;
                const std::uint32_t col = argb(fillOf(i));
                const auto line = [&](const Vec2& a, const Vec2& b) {
                    small_.line(static_cast<float>(a.x()), static_cast<float>(a.y()),
                                static_cast<float>(b.x()), static_cast<float>(b.y()), col);
                };
                line(start, tip);
                const double head = std::min(5.0, 0.5 * (len - r));
                if (clipped.cut) {
                    line(tip + 3.0 * n, tip - 3.0 * n);
                } else if (head >= 2.0) {
                    line(tip, tip - head * u + 0.6 * head * n);
                    line(tip, tip - head * u - 0.6 * head * n);
                }
                continue;
            }
            // Head: a filled triangle with ±30° flanks, at most 12 px and at most the part of
            // the arrow outside the disc; the shaft starts at the rim, never inside the disc.
            const double head = std::min(12.0, len - r);
            const double halfWidth = head * std::tan(std::numbers::pi / 6.0);
            const auto pt = [](const Vec2& v) {
                return SDL_FPoint{static_cast<float>(v.x()), static_cast<float>(v.y())};
            };
            const Color drawn = fillOf(i);
            const SDL_Color col{drawn.r, drawn.g, drawn.b, 255};
            const Vec2 start = c + r * u;
            if (clipped.cut) {
                // Up to the wall, and a bar across its end where the head would be.
                const double hw = 1.0, bar = cutBarHalf(head, hw);
                arrows_.polygon4(pt(start + hw * n), pt(tip + hw * n), pt(tip - hw * n),
                                 pt(start - hw * n), col);
                arrows_.polygon4(pt(tip + bar * n), pt(tip + bar * n - 2.0 * u),
                                 pt(tip - bar * n - 2.0 * u), pt(tip - bar * n), col);
                continue;
            }
            const Vec2 base = tip - head * u;
            arrows_.triangle(pt(tip), pt(base + halfWidth * n), pt(base - halfWidth * n), col);
            if ((base - start).dot(u) > 0.0) {
                const double hw = 1.0;  // shaft half-thickness, pixels
                arrows_.polygon4(pt(start + hw * n), pt(base + hw * n), pt(base - hw * n),
                                 pt(start - hw * n), col);
            }
        }
    }
    // The small discs with their arrows, under the large discs; then the large discs' arrows.
    drawImage(small_, smallLayer_);
    discs_.draw(renderer_, circle_);
    if (options.arrows) {
        // Arrows are opaque; drawn without blending, SDL's software rasteriser fills each
        // triangle about twice as fast (measured: 7.5 against 13.5 ms for 10,000 arrows).
        SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_NONE);
        arrows_.draw(renderer_, nullptr);
        SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_BLEND);
    }
    if (trails != nullptr && options.trails == TrailMode::Selected) {
        drawImage(trails->rasterise(world, camera, options.trails, selected), trailLayer_);
    }

    if (options.labels && labelFont_ != nullptr) {
        visible.resize(particlesVisible);
        if (visible.size() > kMaxLabels) {
            stats.labelsSuppressed = true;
        } else {
            const int lh = labelFont_->lineHeight();
            std::vector<PixelRect> keepOut;
            if (avoid != nullptr) keepOut = avoid->rects;
            // Pegs are as solid as the discs.
            for (const PixelRect& r : pegsOnScreen(world, camera))
                keepOut.push_back(r);
            LabelRoom room =
                labelRoom(world, camera, {0, 0, static_cast<int>(w), static_cast<int>(h)},
                          std::move(keepOut));
            if (avoid != nullptr) {
                room.walls.insert(room.walls.end(), avoid->walls.begin(), avoid->walls.end());
            }
            // One compact form for every label (view/particle_labels.hpp): whose ball, its mass
            // and its velocity, or its name alone.
            std::vector<ParticleLabelText> texts(visible.size());
            std::vector<LabelAsk> asks(visible.size());
            const Axes axes = options.axes(world.def());  // vy up or down, as the user reads it
            for (std::size_t k = 0; k < visible.size(); ++k) {
                const std::size_t i = visible[k];
                // The number the panel and the log name it by (particleNumber).
                texts[k] = particleLabelText(particleNumber(p.id[i]), p.mass[i], p.vx[i],
                                             axes.up(p.vy[i]));
                // A box of fixed pixel size at every zoom, at whole pixels, 2 px clear of the
                // disc (view/label_places.hpp chooses where).
                const Vec2 c = camera.worldToScreen(Vec2(p.x[i], p.y[i]));
                const int cx = static_cast<int>(std::lround(c.x()));
                const int cy = static_cast<int>(std::lround(c.y()));
                const int r = static_cast<int>(std::ceil(camera.toScreen(p.radius[i]))) + kLabelGap;
                const bool inBox = world.def().walls && p.x[i] >= 0.0 && p.y[i] >= 0.0 &&
                                   p.x[i] <= world.def().width && p.y[i] <= world.def().height;
                asks[k] =
                    particleLabelAsk(texts[k], {cx - r, cy - r, 2 * r, 2 * r}, *labelFont_, inBox);
                if (const double len = arrowLength_[k]; len > camera.toScreen(p.radius[i])) {
                    // As drawn: from the rim to the tip, the head's half-width and a pixel.
                    const double speed = std::sqrt(p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
                    const Vec2 u(p.vx[i] / speed, p.vy[i] / speed);
                    const double rim = camera.toScreen(p.radius[i]);
                    const Vec2 from = c + rim * u, tip = c + len * u;
                    const double head = std::min(12.0, len - rim);
                    asks[k].arrow = {from.x(), from.y(), tip.x(), tip.y(),
                                     head * std::tan(std::numbers::pi / 6.0) + 1.0};
                }
            }
            const std::vector<LabelPlace> places = placeLabels(asks, room);
            for (std::size_t k = 0; k < places.size(); ++k) {
                const LabelPlace& place = places[k];
                const PixelRect& box = place.at;
                if (box.w == 0) {
                    // Say why: other labels or panels in the way, or no side of the disc
                    // inside the window at all.
                    ++(place.offWindow ? stats.labelsOffWindow : stats.labelsCrowded);
                    continue;
                }
                if (place.leader) {
                    // From the disc's rim to the label's nearest point: whose label it is
                    // (the line the places were chosen for: it crosses no wall).
                    const LeaderLine line = leaderLine(asks[k].disc, box);
                    const Vec2 from(line.ax, line.ay), near(line.bx, line.by);
                    const Vec2 u = (near - from).normalized();
                    const Vec2 side = Vec2(-u.y(), u.x()) * 0.75;
                    const SDL_Color ink = sdlColor(colours.labelText);
                    const auto pt = [](const Vec2& v) {
                        return SDL_FPoint{static_cast<float>(v.x()), static_cast<float>(v.y())};
                    };
                    labelBoxes_.polygon4(pt(from + side), pt(near + side), pt(near - side),
                                         pt(from - side), ink);
                }
                labelBoxes_.quad(static_cast<float>(box.x), static_cast<float>(box.y),
                                 static_cast<float>(box.x + box.w),
                                 static_cast<float>(box.y + box.h), sdlColor(colours.labelBox));
                {
                    // A thin frame in the text's ink, faint: on the light theme the box is
                    // white on white, and two labels side by side read as one line.
                    const SDL_Color edge = sdlColor(colours.labelText, 110);
                    const auto x0 = static_cast<float>(box.x), y0 = static_cast<float>(box.y);
                    const auto x1 = static_cast<float>(box.x + box.w);
                    const auto y1 = static_cast<float>(box.y + box.h);
                    labelBoxes_.quad(x0, y0, x1, y0 + 1.f, edge);
                    labelBoxes_.quad(x0, y1 - 1.f, x1, y1, edge);
                    labelBoxes_.quad(x0, y0 + 1.f, x0 + 1.f, y1 - 1.f, edge);
                    labelBoxes_.quad(x1 - 1.f, y0 + 1.f, x1, y1 - 1.f, edge);
                }
                const int lineCount = place.nameOnly ? 1 : 2;
                for (int line = 0; line < lineCount; ++line) {
                    const char* text =
                        place.nameOnly ? texts[k].name.c_str()
                                       : texts[k].values[static_cast<std::size_t>(line)].c_str();
                    const float x = static_cast<float>(box.x + 2);
                    const float y = static_cast<float>(box.y + 1 + line * lh);
                    labelFont_->layout(text, x, y, sdlColor(colours.labelText), labelText_);
                }
                ++stats.labelled;
            }
            labelBoxes_.draw(renderer_, nullptr);
            labelFont_->draw(labelText_);
        }
    }
    return stats;
}

}  // namespace psb::app
