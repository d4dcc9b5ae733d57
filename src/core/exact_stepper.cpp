// The exact (event-driven) step; the design note is in exact_stepper.hpp.

#include "exact_stepper.hpp"

#include <algorithm>
#include <cmath>

#include "contact.hpp"
#include "exact_parabolic_impact.hpp"
#include "exact_time_of_impact.hpp"
#include "stage_timer.hpp"

namespace psb::exact {

namespace {

// Cells a little wider than the largest diameter, so that a centre a few ulps outside the cell
// its events say it is in is still found by its neighbours' 3 × 3 searches.
constexpr double kCellSlack = 1.0 + 1e-9;
// Target cell side, in mean particle spacings sqrt(area / N). Larger cells mean fewer
// cell-face events but more pair tests per prediction; measured on the dilute-gas benchmark.
constexpr double kCellSpacings = 1.0;
// A relative velocity below this fraction of the pair's own speeds is rounding (gravity only).
constexpr double kRoundingVelocity = 1e-9;
// Events per particle between two re-sorts of the particles into cell order.
constexpr std::uint64_t kResortEvery = 8;
// Discs up to this many mean spacings across stay in level 0 (one level as before levels
// existed): cells sized by them cost little more than cells a spacing wide. Measured on the
// 1:10 mix of exact_gas_bench (radii 1-10 m, packing 0.2, spacing 18 m): one level was faster
// than levels split at twice the smallest radius.
constexpr double kLevelZeroSpacings = 1.25;
// A level above 0 with fewer than one particle per kSparseCells fine cells is sparse (a few big
// discs); a populous one gets cells of its own size and a thinner skin (setUpLevels).
constexpr double kSparseCells = 32.0;
// The skin, as a fraction of the cell, when a populous level lies above level 0 (0.1 and 0.05
// measured on the 1:10 mix of exact_gas_bench; 0.05 was ~7 % faster).
constexpr double kCrowdedSkin = 0.05;

// Rounds towards minus infinity (cell coordinates may be negative when the grid wraps).
std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

}  // namespace

void ExactStepper::rebuild(ParticleArrays& p, const WorldDef& def) {
    // What was asleep before, where it was (gravity only; see the design note, Resting).
    std::unordered_map<ParticleId, Kept> before;
    const bool sameLaws = gravity_ && def.gravity == def_.gravity && def.width == def_.width &&
                          def.height == def_.height && def.walls == def_.walls &&
                          def.restitution == def_.restitution && def.friction == def_.friction;
    if (sameLaws) {
        for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
            // Each particle as sync() wrote it: one that went on unchanged is no disturbance.
            Body b = bodies_[i];
            if (!(b.flags & kAsleep)) {
                const Motion m = motionAt(i, b, clock_);
                b.x = m.x;
                b.y = m.y;
                b.vx = m.vx;
                b.vy = m.vy;
            }
            before.emplace(ids_[i], Kept{b, depth_[i]});
        }
    }
    def_ = def;
    clock_ = 0.0;
    gx_ = def.gravity.x();
    gy_ = def.gravity.y();
    gravity_ = gx_ != 0.0 || gy_ != 0.0;
    if (gravity_) {
        const double g = std::hypot(gx_, gy_);
        restSpeed_ = def.restitution < 1.0
                         ? kRestSpeed
                         : std::sqrt(2.0 * g * kRestRoundingGap * std::max(def.width, def.height));
        // In a scene of large discs under strong gravity the rest speed is the speed of a hop
        // of kRestHop radii, so that resting means the same there as in a scene at human scale.
        if (def.restitution < 1.0 && p.size() > 0) {
            const double rmin = *std::min_element(p.radius.begin(), p.radius.end());
            restSpeed_ = std::max(restSpeed_, std::sqrt(2.0 * g * kRestHop * rmin));
        }
        restGap_ = restSpeed_ * restSpeed_ / (2.0 * g);
    }
    const auto n = static_cast<std::uint32_t>(p.size());
    bodies_.resize(n);
    cold_.resize(n);
    order_.resize(n);

    ids_ = p.id;
    heldHit_.clear();
    wokeAt_.assign(gravity_ ? n : 0, -kNever);
    depth_.assign(gravity_ ? n : 0, 0);
    recheckAt_.assign(gravity_ ? n : 0, kNever);
    slide_.assign(gravity_ && !def_.obstacles.empty() ? n : 0, Slide{});
    rate_.reset(gravity_ ? n : 0);
    for (std::uint32_t i = 0; i < n; ++i) {
        Body& b = bodies_[i];
        Cold& c = cold_[i];
        b = Body{p.x[i],  p.y[i], p.vx[i],
                 p.vy[i], 0.0,    p.radius[i],
                 kNever,  0,      p.invMass[i] == 0.0 ? kHeld : 0u};
        c = Cold{Event{kNever, 0, 0, Kind::None, 0},
                 p.mass[i],
                 0,
                 0,
                 0,
                 false,
                 false,
                 0,
                 0,
                 p.invMass[i]};
        order_[i] = i;
        if (def_.walls) {
            // Into the box, as the discrete mode's wall stage would; a particle too wide for
            // an axis sits on the centre line with no velocity across it.
            const auto place = [](double& x, double& v, double r, double extent) {
                if (r >= extent - r) {
                    x = 0.5 * extent;
                    v = 0.0;
                    return true;
                }
                x = std::clamp(x, r, extent - r);
                return false;
            };
            c.pinX = place(b.x, b.vx, b.r, def_.width);
            c.pinY = place(b.y, b.vy, b.r, def_.height);
            // A pinned axis has no room to fall along: gravity across it is held by the walls.
            if (gravity_ && c.pinX) b.flags |= kRestX;
            if (gravity_ && c.pinY) b.flags |= kRestY;
        }
    }
    setUpGrid();
    obstacles_.build(def_.obstacles, cells_, skinX_, skinY_,
                     *std::max_element(levelRadius_.begin(), levelRadius_.end()));
    sortByCell(false);
    eventsSinceSort_ = 0;
    for (std::uint32_t i = 0; i < n; ++i)
        insertMember(i);
    recordPlacedOverlaps();
    queue_.reset(2 * n, bucketWidth());
    keptSleepers_ = !before.empty();
    if (keptSleepers_) keepSleepers(before);
    for (std::uint32_t i = 0; i < n; ++i) {
        predictCollision(i, 0.0);
        predictCell(i, 0.0);
    }
    stale_ = false;
}

void ExactStepper::keepSleepers(std::unordered_map<ParticleId, Kept>& before) {
    // A sleeper still where it slept, at rest, sleeps on. Everything else is a disturbance: a
    // particle removed (where it was), added, moved or set in motion (where it is now); the
    // sleepers it touches wake, and with them what rests on them.
    struct Spot {
        double x, y, r;
    };
    std::vector<Spot> spots;
    const auto n = static_cast<std::uint32_t>(bodies_.size());
    std::vector<bool> carried(n, false);  // awake, and going on as it was
    for (std::uint32_t i = 0; i < n; ++i) {
        Body& b = bodies_[i];
        const auto it = before.find(ids_[i]);
        const Body* was = it != before.end() ? &it->second.body : nullptr;
        const bool same = was && was->x == b.x && was->y == b.y && was->r == b.r &&
                          was->vx == b.vx && was->vy == b.vy;
        if (same && (was->flags & kAsleep) && b.vx == 0.0 && b.vy == 0.0 && !(b.flags & kHeld)) {
            // As it slept: at its depth, and a provisional sleep checked again from now.
            b.flags |= was->flags & (kAsleep | kProvisional);
            depth_[i] = it->second.depth;
            recheckAt_[i] = kRecheckAfter;
        } else if (!same || (b.flags & kHeld)) {
            spots.push_back({b.x, b.y, b.r});
        } else {
            carried[i] = true;
        }
        if (it != before.end()) before.erase(it);
    }
    for (const auto& [id, kept] : before)  // removed
        spots.push_back({kept.body.x, kept.body.y, kept.body.r});
    // A change to many particles at once (a setter, a load) starts everything afresh.
    if (spots.size() > kMaxDisturbances) {
        for (Body& b : bodies_)
            b.flags &= ~(kAsleep | kProvisional);
        keptSleepers_ = false;
        return;
    }
    for (const Spot& s : spots) {
        for (std::uint32_t q = 0; q < n; ++q) {
            const Body& b = bodies_[q];
            if (!(b.flags & kAsleep)) continue;
            const double reach = s.r + b.r + restGap_;
            const double dx = b.x - s.x, dy = b.y - s.y;
            if (dx * dx + dy * dy <= reach * reach) wake(q, 0.0);
        }
    }
    // What the changes set free falls: the rattle guard leaves it alone for a while.
    for (std::uint32_t i = 0; i < n; ++i) {
        if (!(bodies_[i].flags & kAsleep) && !carried[i]) rate_.quiet(i, kSettleTime);
    }
}

double ExactStepper::bucketWidth() const {
    // About 1/64 of the time a typical particle takes to cross a cell: the current bucket then
    // holds a few percent of the 2N events, and the 256-bucket calendar spans ~4 crossings.
    double v2 = 0.0;
    for (const Body& b : bodies_)
        v2 += b.vx * b.vx + b.vy * b.vy;
    const double side =
        std::min(cells_.faceX(1) - cells_.faceX(0), cells_.faceY(1) - cells_.faceY(0));
    // Under gravity speeds grow to about √(g·side) within a cell crossing.
    if (gravity_) v2 += static_cast<double>(bodies_.size()) * std::hypot(gx_, gy_) * side;
    if (!(v2 > 0.0)) return 1.0;
    const double vrms = std::sqrt(v2 / static_cast<double>(bodies_.size()));
    return side / vrms / 64.0;
}

void ExactStepper::sortByCell(bool midRun) {
    const auto n = static_cast<std::uint32_t>(bodies_.size());
    const auto cellCount = static_cast<std::size_t>(cells_.nx() * cells_.ny());
    std::vector<std::uint32_t> start(cellCount + 1, 0), cellOf(n), to(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        cellOf[i] = cells_.cell(cold_[i].kx, cold_[i].ky);
        ++start[cellOf[i] + 1];
    }
    for (std::size_t c = 0; c < cellCount; ++c)
        start[c + 1] += start[c];
    for (std::uint32_t i = 0; i < n; ++i)
        to[i] = start[cellOf[i]]++;
    const auto permute = [&](auto& v) {
        std::remove_reference_t<decltype(v)> out(v.size());
        for (std::uint32_t i = 0; i < n; ++i)
            out[to[i]] = v[i];
        v.swap(out);
    };
    permute(bodies_);
    permute(cold_);
    permute(order_);
    permute(ids_);
    if (gravity_) {
        permute(wokeAt_);
        permute(depth_);
        permute(recheckAt_);
        rate_.renumber(to);
    }
    if (!slide_.empty()) permute(slide_);
    if (midRun) {
        // Carry the scheduled events over to the new indices.
        std::vector<double> times(2 * static_cast<std::size_t>(n));
        for (std::uint32_t i = 0; i < n; ++i) {
            times[2 * to[i]] = queue_.timeOf(2 * i);
            times[2 * to[i] + 1] = queue_.timeOf(2 * i + 1);
        }
        for (Cold& c : cold_) {
            if (c.coll.kind == Kind::Pair) c.coll.partner = to[c.coll.partner];
        }
        for (std::uint32_t& i : heldHit_)
            i = to[i];
        queue_.reset(2 * n, queue_.bucketWidth());
        for (std::uint32_t k = 0; k < 2 * n; ++k)
            queue_.update(k, times[k]);
        cells_.clearMembers();
        for (Level& l : upper_)
            l.cells.clearMembers();
        for (std::uint32_t i = 0; i < n; ++i)
            insertMember(i);
    }
}

void ExactStepper::assignLevels(double spacing, double& fineDiameter) {
    const auto n = static_cast<std::uint32_t>(bodies_.size());
    double rmin = kNever;
    for (const Body& b : bodies_)
        rmin = std::min(rmin, b.r);
    // Level 0 holds every disc the cells would be wide enough for anyway (cells are about a
    // mean spacing wide): up to kLevelZeroSpacings spacings across, and at least twice the
    // smallest radius. Above it, levels by factors of two; empty levels are dropped.
    const double level0 = std::max(2.0 * rmin, 0.5 * kLevelZeroSpacings * spacing);
    constexpr int kMaxRaw = 64;
    std::uint8_t raw[kMaxRaw + 1] = {};
    const auto rawLevel = [&](double r) {
        int l = 0;
        for (double limit = level0; r > limit && l < kMaxRaw; limit *= 2.0)
            ++l;
        return l;
    };
    for (const Body& b : bodies_)
        raw[rawLevel(b.r)] = 1;
    std::uint8_t compact[kMaxRaw + 1];
    std::uint8_t count = 0;
    for (int l = 0; l <= kMaxRaw; ++l) {
        compact[l] = count;
        if (raw[l]) ++count;
    }
    levelCount_ = std::max<std::uint8_t>(count, 1);
    levelRadius_.assign(levelCount_, 0.0);
    levelMembers_.assign(levelCount_, 0);
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint8_t l = compact[rawLevel(bodies_[i].r)];
        cold_[i].level = l;
        levelRadius_[l] = std::max(levelRadius_[l], bodies_[i].r);
        ++levelMembers_[l];
    }
    fineDiameter = 2.0 * levelRadius_[0];
}

void ExactStepper::setUpLevels() {
    const auto n = static_cast<std::uint32_t>(bodies_.size());
    const double sx = cells_.faceX(1) - cells_.faceX(0), sy = cells_.faceY(1) - cells_.faceY(0);
    reach_.assign(std::size_t{levelCount_} * levelCount_, 1);
    for (std::uint8_t a = 0; a < levelCount_; ++a) {
        for (std::uint8_t b = 0; b < levelCount_; ++b) {
            if (a == 0 && b == 0) continue;  // the cells are sized for it: the 3 × 3 search
            // Centres in cells k apart along x are at least (k − 1)·sx − 2·skin apart: they can
            // touch only if that is at most the sum of the radii.
            const double sigma = (levelRadius_[a] + levelRadius_[b]) * kCellSlack;
            const double kx = 1.0 + std::floor((sigma + 2.0 * skinX_) / sx);
            const double ky = 1.0 + std::floor((sigma + 2.0 * skinY_) / sy);
            // Capped far beyond any grid (a range wider than the grid is clipped to it), so that
            // a disc of any size gives a representable reach.
            reach_[a * levelCount_ + b] =
                static_cast<std::int64_t>(std::min(std::max(kx, ky), 1e15));
        }
    }
    upper_.resize(levelCount_ - 1u);
    for (std::uint8_t l = 1; l < levelCount_; ++l) {
        Level& level = upper_[l - 1];
        // A sparse level (a few big discs) is listed in blocks as wide as a small disc's reach
        // to it, so that a small disc reads a few empty lists, not (2 reach + 1)²; a populous
        // one in the fine cells themselves, so that no one tests more candidates than its
        // reach holds (a head read costs far less than a candidate's test).
        level.block = populous(l) ? 1 : 2 * reach(0, l) + 1;
        const auto blocks = [&](std::int64_t cells) {
            return std::max<std::int64_t>(1, (cells + level.block - 1) / level.block);
        };
        const auto b = static_cast<double>(level.block);
        level.cells.reset(0.0, 0.0, sx * b, sy * b, blocks(cells_.nx()), blocks(cells_.ny()),
                          cells_.wraps(), n);
    }
}

bool ExactStepper::populous(std::uint8_t level) const {
    // More than one particle in kSparseCells fine cells.
    return static_cast<double>(levelMembers_[level]) * kSparseCells >=
           static_cast<double>(cells_.nx() * cells_.ny());
}

bool ExactStepper::populousUpperLevel() const {
    for (std::uint8_t l = 1; l < levelCount_; ++l) {
        if (populous(l)) return true;
    }
    return false;
}

std::uint32_t ExactStepper::memberCell(std::uint32_t i) const {
    const Cold& c = cold_[i];
    if (c.level == 0) return cells_.cell(c.kx, c.ky);
    const Level& l = upper_[c.level - 1];
    return l.cells.cell(floorDiv(c.kx, l.block), floorDiv(c.ky, l.block));
}

void ExactStepper::insertMember(std::uint32_t i) {
    const std::uint8_t level = cold_[i].level;
    CellList& list = level == 0 ? cells_ : upper_[level - 1].cells;
    list.insert(i, memberCell(i));
}

template <typename F>
void ExactStepper::forCells(std::uint8_t level, std::int64_t x0, std::int64_t x1, std::int64_t y0,
                            std::int64_t y1, F&& f) const {
    const CellList& list = listOf(level);
    if (level > 0) {
        const std::int64_t b = upper_[level - 1].block;
        x0 = floorDiv(x0, b);
        x1 = floorDiv(x1, b);
        y0 = floorDiv(y0, b);
        y1 = floorDiv(y1, b);
    }
    if (list.wraps()) {
        // A range wider than the grid would visit cells twice.
        x1 = std::min(x1, x0 + list.nx() - 1);
        y1 = std::min(y1, y0 + list.ny() - 1);
    } else {
        x0 = std::max<std::int64_t>(x0, 0);
        y0 = std::max<std::int64_t>(y0, 0);
        x1 = std::min(x1, list.nx() - 1);
        y1 = std::min(y1, list.ny() - 1);
    }
    for (std::int64_t ky = y0; ky <= y1; ++ky) {
        for (std::int64_t kx = x0; kx <= x1; ++kx) {
            const std::uint32_t c = list.cell(kx, ky);
            if (c != CellList::kNone) f(c);
        }
    }
}

template <typename F>
void ExactStepper::forEachAround(std::uint32_t i, F&& f) const {
    const Cold& c = cold_[i];
    for (std::uint8_t l = 0; l < levelCount_; ++l) {
        const CellList& list = listOf(l);
        const std::int64_t k = reach(c.level, l);
        forCells(l, c.kx - k, c.kx + k, c.ky - k, c.ky + k, [&](std::uint32_t cell) {
            for (std::uint32_t q = list.head(cell); q != CellList::kNone; q = list.next(q))
                f(q);
        });
    }
}

void ExactStepper::scanBlock(std::uint32_t i, double now, double ax, double ay, std::uint8_t level,
                             std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1,
                             Event& best) {
    const CellList& list = listOf(level);
    constexpr int kCells = 16;
    std::uint32_t cells[kCells];
    int count = 0;
    forCells(level, x0, x1, y0, y1, [&](std::uint32_t c) {
        cells[count++] = c;
        if (count == kCells) {
            scanCells(i, now, ax, ay, list, cells, count, best);
            count = 0;
        }
    });
    if (count > 0) scanCells(i, now, ax, ay, list, cells, count, best);
}

void ExactStepper::scanNeighbours(std::uint32_t i, double now, double ax, double ay, Event& best) {
    const Cold& c = cold_[i];
    for (std::uint8_t l = 0; l < levelCount_; ++l) {
        const std::int64_t k = reach(c.level, l);
        scanBlock(i, now, ax, ay, l, c.kx - k, c.kx + k, c.ky - k, c.ky + k, best);
    }
}

void ExactStepper::setUpGrid() {
    const auto n = static_cast<std::uint32_t>(bodies_.size());
    // Unbounded, so the grid folds onto itself (cell_list.hpp) and need not cover every
    // particle: it is sized for the bulk of them (the middle 90 % along each axis), so
    // that one particle flung far away does not make every cell huge.
    const auto spread = [&](auto coord) {
        if (n < 2) return 0.0;
        std::vector<double> v(n);
        for (std::uint32_t i = 0; i < n; ++i)
            v[i] = coord(bodies_[i]);
        const auto lo = v.begin() + n / 20, hi = v.begin() + (n - 1 - n / 20);
        std::nth_element(v.begin(), lo, v.end());
        const double a = *lo;
        std::nth_element(v.begin(), hi, v.end());
        return *hi - a;
    };
    double bulkW = def_.width, bulkH = def_.height;
    if (!def_.walls) {
        bulkW = spread([](const Body& b) { return b.x; });
        bulkH = spread([](const Body& b) { return b.y; });
    }
    double dmax = 0.0;
    assignLevels(std::sqrt(bulkW * bulkH / std::max(n, 1u)), dmax);
    const double minSide = std::max(dmax * kCellSlack, 1e-300);
    // At most a few cells per particle: enough for the 3 × 3 searches to see ~1 particle each,
    // and memory stays O(N) however large the box.
    const double maxCells = 4.0 * n + 64.0;
    if (def_.walls) {
        const double area = def_.width * def_.height;
        double side = std::max(minSide, kCellSpacings * std::sqrt(area / std::max(n, 1u)));
        side = std::max(side, std::sqrt(area / maxCells));
        const auto count = [&](double extent) {
            // Three cells or fewer: the 3 × 3 search of the middle one already sees the whole
            // width, so one cell sees as much from everywhere and has no faces to cross (in a
            // nearly empty box, cell moves would otherwise outnumber collisions two to one).
            const auto k = static_cast<std::int64_t>(extent / side);
            return k <= 3 ? std::int64_t{1} : k;
        };
        const std::int64_t nx = count(def_.width), ny = count(def_.height);
        cells_.reset(0.0, 0.0, def_.width / static_cast<double>(nx),
                     def_.height / static_cast<double>(ny), nx, ny, false, n);
    } else {
        const double w = bulkW + 2.0 * minSide;
        const double h = bulkH + 2.0 * minSide;
        double side = std::max(minSide, kCellSpacings * std::sqrt(w * h / std::max(n, 1u)));
        side = std::max(side, std::sqrt(w * h / maxCells));
        const auto count = [&](double extent) {
            return std::max<std::int64_t>(3, static_cast<std::int64_t>(std::ceil(extent / side)));
        };
        cells_.reset(0.0, 0.0, side, side, count(w), count(h), true, n);
    }
    // A particle may stray a skin's width out of its cell before it is moved to the next one:
    // two touching discs are then still at most one cell apart (side >= dmax + 2 skin), and a
    // particle that has just moved is a skin's width inside its new cell, so it does not
    // flicker back and forth across a face.
    const double sx = cells_.faceX(1) - cells_.faceX(0), sy = cells_.faceY(1) - cells_.faceY(0);
    skinX_ = std::max(0.0, 0.5 * (sx - minSide));
    skinY_ = std::max(0.0, 0.5 * (sy - minSide));
    if (populousUpperLevel()) {
        // Every reach across levels grows by twice the skin: with many particles above level
        // 0 (cells sized by their spacing, not by level 0's discs), a skin of a tenth of the
        // cell keeps most reaches at one cell (the 3 × 3 search) for a few more cell moves.
        skinX_ = std::min(skinX_, kCrowdedSkin * sx);
        skinY_ = std::min(skinY_, kCrowdedSkin * sy);
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        cold_[i].kx = cells_.coordX(bodies_[i].x);
        cold_[i].ky = cells_.coordY(bodies_[i].y);
    }
    setUpLevels();
}

void ExactStepper::recordPlacedOverlaps() {
    // A pair that overlaps here was placed so from outside (spawned, dragged, clamped into a
    // box too small for its lattice): rounding alone leaves overlaps of a few ulps only. Its
    // contact distance is the distance it was placed at, until it is found apart (scanCells).
    // Colliding it at whatever distance it happens to have instead would be a ratchet: every
    // time it drifts apart the gain is kept, so in a box too full for its discs the overlaps
    // are squeezed out into the gaps of everyone else until the pile jams and the collision
    // rate diverges.
    overlapContact_.clear();
    placedOverlap_ = 0.0;
    const auto n = static_cast<std::uint32_t>(bodies_.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        const Body& a = bodies_[i];
        forEachAround(i, [&](std::uint32_t q) {
            Body& b = bodies_[q];
            if (q <= i || ((a.flags & kHeld) && (b.flags & kHeld))) return;
            const double rx = b.x - a.x, ry = b.y - a.y, sigma = a.r + b.r;
            const double d2 = rx * rx + ry * ry;
            if (!(d2 < sigma * sigma)) return;
            overlapContact_[pairKey(order_[i], order_[q])] = std::sqrt(d2);
            placedOverlap_ = std::max(placedOverlap_, sigma - std::sqrt(d2));
            bodies_[i].flags |= kPlacedOverlapping;
            b.flags |= kPlacedOverlapping;
        });
    }
}

void ExactStepper::advance(std::uint32_t i, double t) {
    Body& b = bodies_[i];
    const double h = t - b.t;
    if (h != 0.0) {
        if (gravity_) {
            double ax, ay;
            accelerationOf(i, b, ax, ay);
            b.x += b.vx * h + 0.5 * ax * h * h;
            b.y += b.vy * h + 0.5 * ay * h * h;
            b.vx += ax * h;
            b.vy += ay * h;
        } else {
            b.x += b.vx * h;
            b.y += b.vy * h;
        }
        b.t = t;
    }
}

void ExactStepper::accelerationOf(std::uint32_t i, const Body& b, double& ax, double& ay) const {
    if (b.flags & (kHeld | kAsleep)) {
        ax = ay = 0.0;
        return;
    }
    if (b.flags & kSliding) {
        // The slide is found by the particle's index, never by the record's address: b may be a
        // copy (rebuild() projects copies of the records to the clock).
        const Slide& s = slide_[i];
        ax = s.ax;
        ay = s.ay;
        return;
    }
    ax = (b.flags & kRestX) ? 0.0 : gx_;
    ay = (b.flags & kRestY) ? 0.0 : gy_;
}

ExactStepper::Motion ExactStepper::motionAt(std::uint32_t i, const Body& b, double t) const {
    Motion m{};
    accelerationOf(i, b, m.ax, m.ay);
    const double h = t - b.t;
    m.x = b.x + b.vx * h + 0.5 * m.ax * h * h;
    m.y = b.y + b.vy * h + 0.5 * m.ay * h * h;
    m.vx = b.vx + m.ax * h;
    m.vy = b.vy + m.ay * h;
    return m;
}

double ExactStepper::pairTimeUnderGravity(const Body& a, const Motion& am, const Body& b,
                                          const Motion& bm, double sigma, double horizon) {
    if (isStatic(a) && isStatic(b)) return kNever;
    const double rx = bm.x - am.x, ry = bm.y - am.y;
    const double dvx = bm.vx - am.vx, dvy = bm.vy - am.vy;
    const double rax = bm.ax - am.ax, ray = bm.ay - am.ay;
    // Falling alike: a straight line relative to each other. Particles that fall together (a
    // pile woken by a rebuild, a stack dropped as one) move at the same velocity to rounding;
    // the direction of a relative velocity made of rounding is noise, so such a pair is at rest
    // relative to each other, not approaching.
    if (rax == 0.0 && ray == 0.0) {
        const double dv2 = dvx * dvx + dvy * dvy;
        const double v2 = am.vx * am.vx + am.vy * am.vy + bm.vx * bm.vx + bm.vy * bm.vy;
        if (dv2 <= kRoundingVelocity * kRoundingVelocity * v2) return kNever;
        return pairImpactTime(rx, ry, dvx, dvy, sigma);
    }
    return parabolicPairImpactTime(rx, ry, dvx, dvy, rax, ray, sigma, horizon);
}

void ExactStepper::scanCells(std::uint32_t i, double now, double ax, double ay,
                             const CellList& list, const std::uint32_t* cells, int cellCount,
                             Event& best) {
    const Body& a = bodies_[i];
    const bool aHeld = (a.flags & kHeld) != 0, aJammed = (a.flags & kJammed) != 0;
    const Motion am = gravity_ ? motionAt(i, a, now) : Motion{};
    // Gather the members first and prefetch their bodies, so that the cache misses of a whole
    // neighbourhood overlap instead of following one another.
    constexpr int kBatch = 32;
    std::uint32_t members[kBatch];
    int k = 0;
    std::uint32_t j = CellList::kNone;
    for (;;) {
        int count = 0;
        while (count < kBatch) {
            if (j == CellList::kNone) {
                if (k == cellCount) break;
                j = list.head(cells[k++]);
                continue;
            }
            if (j != i) {
                members[count++] = j;
                __builtin_prefetch(&bodies_[j]);
            }
            j = list.next(j);
        }
        for (int m = 0; m < count; ++m) {
            const std::uint32_t q = members[m];
            const Body& b = bodies_[q];
            const bool bHeld = (b.flags & kHeld) != 0;
            if (aHeld && bHeld) continue;  // held particles pass through each other
            if ((aJammed && bHeld) || (aHeld && (b.flags & kJammed))) continue;
            const double h = now - b.t;
            Motion bm{};
            double rx, ry;
            if (gravity_) {
                bm = motionAt(q, b, now);
                rx = bm.x - am.x;
                ry = bm.y - am.y;
            } else {
                rx = b.x + b.vx * h - ax;
                ry = b.y + b.vy * h - ay;
            }
            double sigma = a.r + b.r;
            if (a.flags & b.flags & kPlacedOverlapping) {
                const auto it = overlapContact_.find(pairKey(order_[i], order_[q]));
                if (it != overlapContact_.end()) {
                    // Apart at last: from now on the pair is an ordinary one.
                    if (rx * rx + ry * ry >= sigma * sigma) {
                        overlapContact_.erase(it);
                    } else {
                        sigma = it->second;
                    }
                }
            }
            const double t =
                now + (gravity_ ? pairTimeUnderGravity(a, am, b, bm, sigma,
                                                       std::min(best.time, b.nextColl) - now)
                                : pairImpactTime(rx, ry, b.vx - a.vx, b.vy - a.vy, sigma));
            // Only a collision before q's own scheduled collision can happen as predicted: at
            // that time q changes course or is predicted again against everything around it,
            // i included (Smallenburg 2022). Skipping later ones saves stale events.
            if (!(t < b.nextColl)) continue;
            if (t < best.time || (t == best.time && best.kind == Kind::Pair && q < best.partner)) {
                best = {t, q, b.count, Kind::Pair, 0};
            }
        }
        if (count < kBatch) return;
    }
}

void ExactStepper::predictCollision(std::uint32_t i, double now) {
    const Body& a = bodies_[i];
    const Cold& ac = cold_[i];
    // Where i is now. Its stored position stays that of its last velocity change: re-deriving
    // it at every cell face would add a rounding error per face crossed.
    const double ha = now - a.t;
    double ax = a.x + a.vx * ha, ay = a.y + a.vy * ha;
    Event best{kNever, 0, 0, Kind::None, 0};

    Motion m{ax, ay, a.vx, a.vy, 0.0, 0.0};
    if (gravity_) {
        m = motionAt(i, a, now);
        ax = m.x;
        ay = m.y;
        if (def_.walls) predictWallsUnderGravity(i, m, now, best);
    } else if (def_.walls) {
        // A pinned axis has no room: any velocity across it is absorbed at once.
        double tw[4] = {kNever, kNever, kNever, kNever};  // left, right, top, bottom
        if (ac.pinX) {
            if (a.vx != 0.0) tw[a.vx > 0.0 ? 1 : 0] = 0.0;
        } else {
            tw[0] = wallImpactTime(ax, a.vx, a.r, -1.0);
            tw[1] = wallImpactTime(ax, a.vx, def_.width - a.r, 1.0);
        }
        if (ac.pinY) {
            if (a.vy != 0.0) tw[a.vy > 0.0 ? 3 : 2] = 0.0;
        } else {
            tw[2] = wallImpactTime(ay, a.vy, a.r, -1.0);
            tw[3] = wallImpactTime(ay, a.vy, def_.height - a.r, 1.0);
        }
        for (std::int8_t side = 0; side < 4; ++side) {
            // Durations >= 0 added to the current time: never an event in the past.
            if (now + tw[side] < best.time) best = {now + tw[side], 0, 0, Kind::Wall, side};
        }
    }
    if (!obstacles_.empty()) {
        predictObstacles(i, m, now, best);
        if (a.flags & kSliding) predictSlide(i, m, now, best);
    }
    scanNeighbours(i, now, ax, ay, best);
    if ((a.flags & kProvisional) && recheckAt_[i] < best.time)
        best = {std::max(now, recheckAt_[i]), 0, 0, Kind::Recheck, 0};
    cold_[i].coll = best;
    bodies_[i].nextColl = best.time;
    queue_.update(2 * i, best.time);
}

void ExactStepper::predictWallsUnderGravity(std::uint32_t i, const Motion& m, double now,
                                            Event& best) const {
    const Body& a = bodies_[i];
    const Cold& ac = cold_[i];
    double tw[4] = {kNever, kNever, kNever, kNever};  // left, right, top, bottom
    if (ac.pinX) {
        if (m.vx != 0.0) tw[m.vx > 0.0 ? 1 : 0] = 0.0;
    } else {
        tw[0] = crossingTime(m.x, m.vx, m.ax, a.r, -1.0);
        tw[1] = crossingTime(m.x, m.vx, m.ax, def_.width - a.r, 1.0);
    }
    if (ac.pinY) {
        if (m.vy != 0.0) tw[m.vy > 0.0 ? 3 : 2] = 0.0;
    } else {
        tw[2] = crossingTime(m.y, m.vy, m.ay, a.r, -1.0);
        tw[3] = crossingTime(m.y, m.vy, m.ay, def_.height - a.r, 1.0);
    }
    for (std::int8_t side = 0; side < 4; ++side) {
        if (now + tw[side] < best.time) best = {now + tw[side], 0, 0, Kind::Wall, side};
    }
}

void ExactStepper::predictCell(std::uint32_t i, double now) {
    const Body& a = bodies_[i];
    const Cold& ac = cold_[i];
    const double ha = now - a.t;
    Motion m{a.x + a.vx * ha, a.y + a.vy * ha, a.vx, a.vy, 0.0, 0.0};
    if (gravity_) m = motionAt(i, a, now);
    const auto exitTime = [&](double x, double v, double acc, double lo, double hi, int& f) {
        return gravity_ ? slabExitTimeAccelerated(x, v, acc, lo, hi, f)
                        : slabExitTime(x, v, lo, hi, f);
    };
    double best = kNever;
    std::int8_t side = 0;
    // With walls the outer faces are never crossed (the wall comes first).
    int face;
    const double tx = exitTime(m.x, m.vx, m.ax, cells_.faceX(ac.kx) - skinX_,
                               cells_.faceX(ac.kx + 1) + skinX_, face);
    const bool outerX =
        !cells_.wraps() && ((face < 0 && ac.kx == 0) || (face > 0 && ac.kx == cells_.nx() - 1));
    if (face != 0 && !outerX) {
        best = tx;
        side = face < 0 ? 0 : 1;
    }
    const double ty = exitTime(m.y, m.vy, m.ay, cells_.faceY(ac.ky) - skinY_,
                               cells_.faceY(ac.ky + 1) + skinY_, face);
    const bool outerY =
        !cells_.wraps() && ((face < 0 && ac.ky == 0) || (face > 0 && ac.ky == cells_.ny() - 1));
    if (face != 0 && !outerY && ty < best) {
        best = ty;
        side = face < 0 ? 2 : 3;
    }
    cold_[i].cellSide = side;
    queue_.update(2 * i + 1, now + best);
}

bool ExactStepper::collidedWithin(const Body& b, double now) {
    // t is the time of b's last velocity change; count > 0 says there was one since the last
    // rebuild (t = 0 at a rebuild is not a collision).
    return b.count > 0 && now - b.t < kContactDuration;
}

double ExactStepper::effectiveRestitution(double impactSpeed, bool recent) const {
    const double e = def_.restitution;
    if (e >= 1.0 || recent) return 1.0;
    if (impactSpeed >= kElasticBelowSpeed) return e;
    return 1.0 - (1.0 - e) * (impactSpeed / kElasticBelowSpeed);
}

void ExactStepper::handlePair(std::uint32_t i, const Event& ev, StepCounters& counters) {
    const std::uint32_t j = ev.partner;
    __builtin_prefetch(&cold_[j]);
    queue_.prefetch(2 * j);
    Body& a = bodies_[i];
    Body& b = bodies_[j];
    if (b.count != ev.partnerCount) {
        ++events_;  // stale: j changed course after this was predicted
        predictCollision(i, ev.time);
        return;
    }
    ++events_;
    const bool recent = collidedWithin(a, ev.time) || collidedWithin(b, ev.time);
    // A sleeper does not move; advancing it would only restart its clock (t).
    if (!(a.flags & kAsleep)) advance(i, ev.time);
    if (!(b.flags & kAsleep)) advance(j, ev.time);
    // A pair event ends a slide (the pair's impulses and lift are those of free particles); a
    // slider still on its face afterwards slides on (keepOnFace below). Its acceleration has
    // changed, so its counter does too.
    const bool aSlid = (a.flags & kSliding) != 0, bSlid = (b.flags & kSliding) != 0;
    if (aSlid) {
        stopSliding(a);
        ++a.count;
    }
    if (bSlid) {
        stopSliding(b);
        ++b.count;
    }
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double d = std::sqrt(dx * dx + dy * dy);
    maxOverlap_ = std::max(maxOverlap_, a.r + b.r - d);
    Normal n;
    if (d > 0.0 && std::isfinite(dx / d) && std::isfinite(dy / d)) {
        n = {dx / d, dy / d};
    } else {
        n = coincidentNormal(ids_[i], ids_[j]);
    }
    const double approach = (a.vx - b.vx) * n.x + (a.vy - b.vy) * n.y;
    // A sleeper hit hard enough, or by a held particle, wakes; otherwise it stays put and the
    // other bounces off it as off an infinitely heavy disc.
    bool aStays = false, bStays = false, woke = false;
    if (gravity_) {
        const auto hitsSleeper = [&](std::uint32_t s, std::uint32_t o) {
            if (!(bodies_[s].flags & kAsleep)) return false;
            // A particle wedged between sleepers (no room between them) would bounce between
            // them ever faster: after kWakeAfterHits such hits in a step it wakes them, and the
            // wedge opens as it would, by pushing them apart.
            if ((bodies_[o].flags & kHeld) || approach > 2.0 * restSpeed_ ||
                countHit(o) >= kWakeAfterHits) {
                wake(s, ev.time);
                woke = true;
                return false;
            }
            return true;
        };
        aStays = hitsSleeper(i, j);
        bStays = hitsSleeper(j, i);
    }
    const double wi = aStays ? 0.0 : cold_[i].w, wj = bStays ? 0.0 : cold_[j].w;
    // Off a sleeper, which does not move, a bounce cannot start a collapse: the TC model's
    // elastic rule would only keep a particle wedged between sleepers rattling at full speed.
    const bool offStatic = aStays || bStays;
    double e = effectiveRestitution(approach, recent && !offStatic);
    // And a rebound off it slower than the rest speed ends the approach, as on a wall the
    // particle rests on: a particle in a slot between sleepers stops instead of rattling.
    if (offStatic && approach * e < restSpeed_) e = 0.0;
    const bool hit = def_.friction > 0.0
                         ? collideDiscs<true>(a.vx, a.vy, b.vx, b.vy, wi, wj, cold_[i].m,
                                              cold_[j].m, n, e, def_.friction)
                         : collideDiscs<false>(a.vx, a.vy, b.vx, b.vy, wi, wj, cold_[i].m,
                                               cold_[j].m, n, e, 0.0);
    if (hit) {
        ++counters.collisions;
        if (!aStays) ++a.count;
        if (!bStays) ++b.count;
        if (b.flags & kHeld) countHeldHit(i);
        if (a.flags & kHeld) countHeldHit(j);
        if (log_) log_->push_back({ev.time, order_[i], order_[j]});
    }
    if (gravity_) {
        // Lift what gravity presses together (judged by how they moved into the contact), then
        // let them rest (what this hit just woke does not).
        liftPressedPair(i, j, n, aSlid, bSlid);
        // A slider pressed along its face into a neighbour without an impulse (at rest against
        // it) would slide into it again at once, the same event at the same instant without
        // end: it hops off the face instead, as before slides, and slides again when it lands.
        if (aSlid) keepOnFace(i, counters, hit);
        if (bSlid) keepOnFace(j, counters, hit);
        settleAfterPair(i, woke);
        settleAfterPair(j, woke);
    }
    predictCollision(i, ev.time);
    predictCollision(j, ev.time);
    predictCell(i, ev.time);
    predictCell(j, ev.time);
}

std::uint32_t ExactStepper::countHit(std::uint32_t i) {
    if (cold_[i].heldHits++ == 0) heldHit_.push_back(i);
    return cold_[i].heldHits;
}

void ExactStepper::countHeldHit(std::uint32_t i) {
    if (countHit(i) >= kJamLimit) bodies_[i].flags |= kJammed;
}

void ExactStepper::handleWall(std::uint32_t i, const Event& ev, StepCounters& counters) {
    Body& a = bodies_[i];
    const bool recent = collidedWithin(a, ev.time);
    advance(i, ev.time);
    stopSliding(a);
    ++events_;
    const bool alongX = ev.side < 2;
    double& v = alongX ? a.vx : a.vy;
    double& vt = alongX ? a.vy : a.vx;
    const double outward = (ev.side % 2 == 0) ? -1.0 : 1.0;
    const bool pinned = alongX ? cold_[i].pinX : cold_[i].pinY;
    if (gravity_ && !pinned) {
        // At the wall by definition of the event: a parabola's root can leave the centre a few
        // ulps past it, which a particle resting there would keep.
        double& x = alongX ? a.x : a.y;
        const double extent = alongX ? def_.width : def_.height;
        x = std::clamp(x, a.r, extent - a.r);
    }
    double dv = 0.0;
    if (a.flags & kHeld) {
        // A held particle stops moving across the wall; its owner sets its velocity again.
        if (outward * v > 0.0) v = 0.0;
    } else if (pinned) {
        dv = std::abs(v);
        v = 0.0;
    } else {
        double out = outward * v;
        const double e = effectiveRestitution(out, recent);
        dv = def_.friction > 0.0 ? reboundOffWall<true>(out, vt, e, def_.friction)
                                 : reboundOffWall<false>(out, vt, e, 0.0);
        v = outward * out;
        // Pressed into this wall by gravity and leaving it too slowly to fly: it rests on it.
        if (gravity_ && outward * (alongX ? gx_ : gy_) > 0.0 && std::abs(v) < restSpeed_) {
            dv += std::abs(v);
            v = 0.0;
            a.flags |= alongX ? kRestX : kRestY;
        }
    }
    if (dv > 0.0) {
        ++counters.wallCollisions;
        counters.wallImpulse += cold_[i].m * dv;
        if (log_) log_->push_back({ev.time, order_[i], CollisionRecord::kWall + ev.side});
    }
    ++a.count;
    if (gravity_ && !(a.flags & kHeld))
        settle(i, ev.time,
               a.vx * a.vx + a.vy * a.vy < restSpeed_ * restSpeed_ && mayRest(i, ev.time));
    predictCollision(i, ev.time);
    predictCell(i, ev.time);
}

void ExactStepper::liftPressedPair(std::uint32_t i, std::uint32_t j, Normal n, bool aSlid,
                                   bool bSlid) {
    Body& a = bodies_[i];
    Body& b = bodies_[j];
    const double wi = (a.flags & (kAsleep | kHeld)) ? 0.0 : cold_[i].w;
    const double wj = (b.flags & (kAsleep | kHeld)) ? 0.0 : cold_[j].w;
    if (wi == 0.0 && wj == 0.0) return;
    // Pressed together by gravity (one falls, the other does not, or less) and leaving each
    // other slower than the lift: leave at the lift, by an impulse along n shared as a
    // collision shares it (see the design note).
    // A slider the pair event took off its face is still on it: judged by how it moved into
    // the contact, it does not fall (else a ball at rest on a slider, both woken at once, would
    // meet it again at the same instant without end).
    double aax, aay, bax, bay;
    accelerationOf(i, a, aax, aay);
    accelerationOf(j, b, bax, bay);
    if (aSlid) aax = slide_[i].ax, aay = slide_[i].ay;
    if (bSlid) bax = slide_[j].ax, bay = slide_[j].ay;
    const double rax = bax - aax, ray = bay - aay, an = rax * n.x + ray * n.y;
    if (!(an < 0.0 && an * an > kPressTolerance * kPressTolerance * (rax * rax + ray * ray)))
        return;
    const double lift = 0.5 * restSpeed_;
    const double leaving = (b.vx - a.vx) * n.x + (b.vy - a.vy) * n.y;
    if (!(leaving < lift)) return;
    const double dv = lift - leaving, share = wi / (wi + wj);
    a.vx -= dv * share * n.x;
    a.vy -= dv * share * n.y;
    b.vx += dv * (1.0 - share) * n.x;
    b.vy += dv * (1.0 - share) * n.y;
    if (wi > 0.0) ++a.count;
    if (wj > 0.0) ++b.count;
}

void ExactStepper::settleAfterPair(std::uint32_t i, bool justWoken) {
    Body& a = bodies_[i];
    if (a.flags & (kHeld | kAsleep)) return;
    // Off the wall it rested on if the pair pushed it off (or into it: the wall event comes
    // at once and decides).
    const Cold& ac = cold_[i];
    if ((a.flags & kRestX) && !ac.pinX && a.vx != 0.0) a.flags &= ~kRestX;
    if ((a.flags & kRestY) && !ac.pinY && a.vy != 0.0) a.flags &= ~kRestY;
    settle(i, a.t,
           !justWoken && a.vx * a.vx + a.vy * a.vy < restSpeed_ * restSpeed_ && mayRest(i, a.t));
}

ExactStepper::Hold ExactStepper::hold(std::uint32_t i, std::uint32_t below, double now) const {
    // The contact normals (from i to what holds it) of everything within restGap_ that does not
    // move: walls, obstacles, held particles at rest (depth 0), sleepers (their depth); then the
    // same with the slow free neighbours added. holdsAgainstGravity says whether they hold i.
    const Body& a = bodies_[i];
    constexpr int kMax = 16;
    double nx[kMax], ny[kMax];
    int count = 0;
    std::uint32_t lowest = kUngrounded;  // the least depth of a static support below `below`
    const auto add = [&](double x, double y) {
        if (count < kMax) nx[count] = x, ny[count++] = y;
    };
    if (def_.walls) {
        if (a.x - a.r <= restGap_) add(-1.0, 0.0);
        if (def_.width - a.r - a.x <= restGap_) add(1.0, 0.0);
        if (a.y - a.r <= restGap_) add(0.0, -1.0);
        if (def_.height - a.r - a.y <= restGap_) add(0.0, 1.0);
    }
    if (!obstacles_.empty()) count = obstacleSupports(i, nx, ny, count, kMax);
    if (count > 0) lowest = 0;
    // Slow free neighbours, kept apart: a sleep that needs them is provisional (see the design
    // note). With e = 1 only what is static holds; a neighbour rebuilt or woken less than
    // kRecheckAfter ago may be falling away.
    double fx[kMax], fy[kMax];
    int free = 0;
    const bool freeCount = def_.restitution < 1.0 && (keptSleepers_ || now >= kSettleTime);
    forEachAround(i, [&](std::uint32_t q) {
        const Body& b = bodies_[q];
        if (q == i || (b.flags & kHeld && !isStatic(b))) return;
        const bool still = isStatic(b);
        double bx = b.x, by = b.y;  // a static b does not move: b.x is now
        if (!still) {
            // After a rebuild that kept the sleepers only what it set free or added is
            // settling, not everything.
            if (!freeCount || now - wokeAt_[q] < kRecheckAfter) return;
            if (keptSleepers_ && rate_.quietAt(q, now)) return;
            const Motion m = motionAt(q, b, now);
            if (m.vx * m.vx + m.vy * m.vy >= restSpeed_ * restSpeed_) return;
            bx = m.x;
            by = m.y;
        }
        const double rx = bx - a.x, ry = by - a.y;
        const double d = std::sqrt(rx * rx + ry * ry);
        if (!(d > 0.0 && d - (a.r + b.r) <= restGap_)) return;
        if (!still) {
            if (free < kMax) fx[free] = rx / d, fy[free++] = ry / d;
            return;
        }
        add(rx / d, ry / d);
        const std::uint32_t depth = (b.flags & kAsleep) ? depth_[q] : 0;
        if (depth < below) lowest = std::min(lowest, depth);
    });
    Hold h;
    h.depth = lowest >= kUngrounded ? kUngrounded : lowest + 1;
    h.firm = lowest < kUngrounded && holdsAgainstGravity(nx, ny, count);
    if (h.firm || count == 0 || free == 0) return h;
    // An arch of discs leaning on each other would wait for the others to sleep first, and
    // none would: the slow free neighbours count too, as long as something static is among the
    // supports (two discs falling side by side have nothing static).
    const int statics = count;
    for (int k = 0; k < free; ++k)
        add(fx[k], fy[k]);
    h.withFree = count > statics && holdsAgainstGravity(nx, ny, count);
    return h;
}

bool ExactStepper::holdsAgainstGravity(const double* nx, const double* ny, int count) const {
    // Without friction: gravity in the cone of the normals, along one of them (to 1e-9 rad) or
    // strictly between two less than a half turn apart. Anything else lets i move down.
    const double pi = 3.14159265358979323846;
    const double ga = std::atan2(gy_, gx_);
    double lo = -kNever, hi = kNever;  // the nearest normals on either side of gravity
    bool left = false, right = false;
    for (int k = 0; k < count; ++k) {
        double d = std::atan2(ny[k], nx[k]) - ga;  // angle from gravity to normal k, (-pi, pi]
        if (d > pi) d -= 2.0 * pi;
        if (d <= -pi) d += 2.0 * pi;
        if (std::abs(d) <= 1e-9) return true;
        if (d < 0.0 && d > lo) lo = d, left = true;
        if (d > 0.0 && d < hi) hi = d, right = true;
    }
    if (left && right && hi - lo < pi - 1e-9) return true;
    // Then i slides down the face of one support that gravity presses it into, the one that no
    // other support blocks (or falls free if it presses into none). Friction holds it there
    // only if that face is tilted less than the friction angle: it carries i's whole weight.
    // (Widening every normal's cone by the friction angle instead would count a neighbour that
    // the slide only grazes as pushing, with any force: a grain between one above and one
    // below it would be held, and the grains above a neck would lock into a fake arch.)
    const double g = std::hypot(gx_, gy_), ux = gx_ / g, uy = gy_ / g;
    bool pressed = false;
    for (int k = 0; k < count; ++k) {
        const double c = ux * nx[k] + uy * ny[k];  // cos of the face's tilt
        if (!(c > 0.0)) continue;
        pressed = true;
        const double tx = ux - c * nx[k], ty = uy - c * ny[k];  // down the face, |t| = sin tilt
        bool blocked = false;
        for (int m = 0; m < count && !blocked; ++m)
            blocked = m != k && tx * nx[m] + ty * ny[m] > 1e-9;
        if (!blocked && std::sqrt(tx * tx + ty * ty) > def_.friction * c + 1e-9) return false;
    }
    return pressed;
}

void ExactStepper::settle(std::uint32_t i, double now, bool slow) {
    // Slow and held by what does not move: asleep for good. Held only with slow free
    // neighbours' help, or caught rattling: asleep until a recheck kRecheckAfter later.
    Hold h;
    if (slow) {
        h = hold(i, kUngrounded + 1, now);
        if (h.firm) {
            fallAsleep(i, now, h.depth, false);
            return;
        }
        if (h.withFree) {
            fallAsleep(i, now, h.depth, true);
            return;
        }
    }
    if (!rattles(i, now)) return;
    if (!slow) h = hold(i, kUngrounded + 1, now);
    fallAsleep(i, now, h.depth, !h.firm);
}

void ExactStepper::fallAsleep(std::uint32_t i, double now, std::uint32_t depth, bool provisional) {
    Body& b = bodies_[i];
    advance(i, now);
    b.vx = b.vy = 0.0;
    b.flags |= kAsleep;
    depth_[i] = depth;
    if (provisional) {
        b.flags |= kProvisional;
        recheckAt_[i] = now + kRecheckAfter;
    }
    stopSliding(b);
    ++b.count;
}

void ExactStepper::handleRecheck(std::uint32_t i, const Event& ev) {
    // A provisional sleeper: held now by what does not move, with a support nearer the ground
    // than itself, it sleeps for good; still held with slow free neighbours' help, it waits
    // another kRecheckAfter; else it wakes (and what it holds up, see wake()).
    Body& a = bodies_[i];
    a.flags &= ~kProvisional;
    const Hold h = hold(i, depth_[i], ev.time);
    if (h.firm) {
        depth_[i] = std::min(depth_[i], h.depth);
    } else if (h.withFree) {
        sleepNeighboursAtRest(i, ev.time);
        a.flags |= kProvisional;
        recheckAt_[i] = ev.time + kRecheckAfter;
    } else {
        wake(i, ev.time);
        predictCell(i, ev.time);
    }
    predictCollision(i, ev.time);
}

void ExactStepper::sleepNeighboursAtRest(std::uint32_t i, double now) {
    // A free neighbour with no velocity and no acceleration (one woken or hit at rest on the
    // floor, say) has no event of its own to fall asleep at, and would keep i provisional for
    // ever: it falls asleep now if what is static holds it.
    const Body& a = bodies_[i];
    forEachAround(i, [&](std::uint32_t q) {
        const Body& b = bodies_[q];
        if (q == i || (b.flags & (kAsleep | kHeld)) || b.vx != 0.0 || b.vy != 0.0) return;
        double ax, ay;
        accelerationOf(q, b, ax, ay);
        if (ax != 0.0 || ay != 0.0 || !mayRest(q, now)) return;
        const double rx = b.x - a.x, ry = b.y - a.y, reach = a.r + b.r + restGap_;
        if (rx * rx + ry * ry > reach * reach) return;
        const Hold h = hold(q, kUngrounded + 1, now);
        if (!h.firm) return;
        fallAsleep(q, now, h.depth, false);
        predictCollision(q, now);
        predictCell(q, now);
    });
}

void ExactStepper::wake(std::uint32_t i, double now) {
    // i wakes, and with it every sleeper it held up: a sleeper nearer the ground does not rest
    // on i (see the design note); one farther from it that what stays asleep no longer holds
    // (with a support nearer the ground than itself) wakes in turn.
    const auto rouse = [&](std::uint32_t k) {
        // It still rests on the walls it rested on (until it moves off them): what presses it
        // into them is then lifted off it, not pressed through it.
        Body& b = bodies_[k];
        b.flags &= ~(kAsleep | kProvisional);
        b.t = now;
        wokeAt_[k] = now;
        ++b.count;
    };
    rouse(i);
    wakeStack_.assign(1, i);
    while (!wakeStack_.empty()) {
        const std::uint32_t p = wakeStack_.back();
        wakeStack_.pop_back();
        const Body& a = bodies_[p];
        forEachAround(p, [&](std::uint32_t q) {
            Body& b = bodies_[q];
            if (!(b.flags & kAsleep)) return;
            const double rx = b.x - a.x, ry = b.y - a.y;
            const double reach = a.r + b.r + restGap_;
            if (rx * rx + ry * ry > reach * reach) return;
            const Hold h = hold(q, depth_[q], now);
            if (h.firm) return;
            if (h.withFree) {
                // Held now only with slow free neighbours' help: provisional, as if it had just
                // fallen asleep so (one that already is keeps its recheck).
                if (!(b.flags & kProvisional)) {
                    b.flags |= kProvisional;
                    recheckAt_[q] = now + kRecheckAfter;
                    predictCollision(q, now);
                }
                return;
            }
            rouse(q);
            predictCollision(q, now);
            predictCell(q, now);
            wakeStack_.push_back(q);
        });
    }
}

void ExactStepper::handleCell(std::uint32_t i, double now) {
    Cold& a = cold_[i];
    ++events_;
    const std::uint32_t oldCell = memberCell(i);
    const std::int8_t side = a.cellSide;  // predictCell below overwrites it
    switch (side) {
        case 0:
            --a.kx;
            break;
        case 1:
            ++a.kx;
            break;
        case 2:
            --a.ky;
            break;
        default:
            ++a.ky;
            break;
    }
    if (a.level == 0) {
        cells_.erase(i);
        cells_.insert(i, cells_.cell(a.kx, a.ky));
    } else if (const std::uint32_t cell = memberCell(i); cell != oldCell) {
        CellList& list = upper_[a.level - 1].cells;
        list.erase(i);
        list.insert(i, cell);
    }
    predictCell(i, now);

    // The cells that just came within reach at each level: the far column (or row) in the
    // direction of motion (for two of level 0, the three cells that just came into i's 3 × 3
    // neighbourhood). Everything else within reach was searched by i's last full prediction,
    // whose earliest result is still scheduled, so only these can bring an earlier event.
    const Body& b = bodies_[i];
    const double h = now - b.t;
    double ax = b.x + b.vx * h, ay = b.y + b.vy * h;
    Motion m{ax, ay, b.vx, b.vy, 0.0, 0.0};
    if (gravity_) {
        m = motionAt(i, b, now);
        ax = m.x;
        ay = m.y;
    }
    Event best = a.coll;
    for (std::uint8_t l = 0; l < levelCount_; ++l) {
        const std::int64_t k = reach(a.level, l);
        switch (side) {
            case 0:
                scanBlock(i, now, ax, ay, l, a.kx - k, a.kx - k, a.ky - k, a.ky + k, best);
                break;
            case 1:
                scanBlock(i, now, ax, ay, l, a.kx + k, a.kx + k, a.ky - k, a.ky + k, best);
                break;
            case 2:
                scanBlock(i, now, ax, ay, l, a.kx - k, a.kx + k, a.ky - k, a.ky - k, best);
                break;
            default:
                scanBlock(i, now, ax, ay, l, a.kx - k, a.kx + k, a.ky + k, a.ky + k, best);
                break;
        }
    }
    // The new cell's obstacles (the old cell's are in a.coll already, or later than it).
    if (!obstacles_.empty()) predictObstacles(i, m, now, best);
    if (best.time < a.coll.time) {
        a.coll = best;
        bodies_[i].nextColl = best.time;
        queue_.update(2 * i, best.time);
    }
}

double ExactStepper::runEvents(double tEnd, StepCounters& counters, std::uint64_t budget) {
    std::uint64_t processed = 0;
    for (;;) {
        const EventQueue::Entry top = queue_.top();
        if (!(top.time <= tEnd)) break;
        if (++processed > budget) {
            if (!gravity_) {
                stale_ = true;  // fly the rest freely; the next step rebuilds
                flewFreely_ = true;
                return tEnd;
            }
            // Under gravity flying freely would drop particles through the floor and into each
            // other. The state is exact up to the next event: the step ends there, the time
            // left is not simulated, and the next step goes on from there, the queue as it is.
            return top.time;
        }
        if (++eventsSinceSort_ > kResortEvery * bodies_.size()) {
            // Particles drift away from the neighbours they were stored next to; restoring
            // cell order keeps each 3 × 3 search in a few cache lines. Indices only change:
            // no position, velocity or event time is touched.
            sortByCell(true);
            eventsSinceSort_ = 0;
            continue;
        }
        // Events come in time order, which is random in space: the next particle's lines are
        // almost never in cache. Start fetching them while this event is handled.
        if (const std::uint32_t next = queue_.likelyNext(); next != UINT32_MAX) {
            __builtin_prefetch(&bodies_[next / 2]);
            __builtin_prefetch(&cold_[next / 2]);
            queue_.prefetch(next);
        }
        const std::uint32_t i = top.key / 2;
        if (top.key % 2 == 1) {
            handleCell(i, top.time);
            continue;
        }
        const Event ev = cold_[i].coll;
        switch (ev.kind) {
            case Kind::Pair:
                handlePair(i, ev, counters);
                break;
            case Kind::Wall:
                handleWall(i, ev, counters);
                break;
            case Kind::Obstacle:
                handleObstacle(i, ev, counters);
                break;
            case Kind::Slide:
                handleSlide(i, ev);
                break;
            case Kind::Recheck:
                handleRecheck(i, ev);
                break;
            case Kind::None:
                return tEnd;  // unreachable: None events are at +infinity
        }
    }
    return tEnd;
}

void ExactStepper::sync(ParticleArrays& p) {
    // One pass in the stepper's order; every particle's state at the end of the last step.
    const std::size_t n = bodies_.size();
    const double t = clock_;
    const Body* bodies = bodies_.data();
    const std::uint32_t* order = order_.data();
    double* x = p.x.data();
    double* y = p.y.data();
    double* vx = p.vx.data();
    double* vy = p.vy.data();
    for (std::size_t k = 0; k < n; ++k) {
        const Body& b = bodies[k];
        const std::uint32_t i = order[k];
        if (gravity_) {
            const Motion m = motionAt(k, b, t);
            x[i] = m.x;
            y[i] = m.y;
            vx[i] = m.vx;
            vy[i] = m.vy;
            continue;
        }
        const double h = t - b.t;
        x[i] = b.x + b.vx * h;
        y[i] = b.y + b.vy * h;
        vx[i] = b.vx;
        vy[i] = b.vy;
    }
    if (flewFreely_ && def_.walls) {
        // Past a wall after the free flight (a particle the budget stopped between a wall and
        // an obstacle it was placed in, say): on the wall, turned inward with restitution e.
        const auto axis = [e = def_.restitution](double& c, double& v, double r, double extent) {
            if (r >= extent - r) {
                c = 0.5 * extent;
                v = 0.0;
            } else if (c < r) {
                c = r;
                if (v < 0.0) v = -e * v;
            } else if (c > extent - r) {
                c = extent - r;
                if (v > 0.0) v = -e * v;
            }
        };
        for (std::size_t i = 0; i < n; ++i) {
            axis(x[i], vx[i], p.radius[i], def_.width);
            axis(y[i], vy[i], p.radius[i], def_.height);
        }
    }
    flewFreely_ = false;
    syncOwed_ = false;
}

void ExactStepper::step(ParticleArrays& p, const WorldDef& def, double dt, StepProfile& profile,
                        StepCounters& counters) {
    StageTimer total(profile.total);
    double& rebuildMs = profile.stage("rebuild");
    double& eventsMs = profile.stage("events");
    profile.stage("sync");  // added by World when the state is read
    if (stale_) {
        // The world's arrays must hold the current state before they are read back in (after
        // an exhausted budget the stepper invalidates itself with a sync still owed).
        if (syncOwed_) sync(p);
        StageTimer t(rebuildMs);
        rebuild(p, def);
        // Pairs placed overlapping are part of the state: report them, not only the overlaps
        // met at collisions (which rounding keeps at a few ulps).
        counters.maxOverlap = std::max(counters.maxOverlap, placedOverlap_);
    }
    events_ = 0;
    // The jam guard counts per step: clear only the particles it counted in the last one.
    for (const std::uint32_t i : heldHit_) {
        bodies_[i].flags &= ~kJammed;
        cold_[i].heldHits = 0;
    }
    heldHit_.clear();
    maxOverlap_ = counters.maxOverlap;
    const double tEnd = clock_ + dt;
    const std::uint64_t budget = kMaxEventsPerParticlePerStep * (bodies_.size() + 1);
    double reached = tEnd;
    {
        StageTimer t(eventsMs);
        reached = runEvents(tEnd, counters, budget);
    }
    clock_ = reached;
    syncOwed_ = !bodies_.empty();
    counters.maxOverlap = std::max(counters.maxOverlap, maxOverlap_);
    counters.events += events_;
    ++counters.steps;
}

std::size_t ExactStepper::memoryBytes() const {
    std::size_t bytes = sizeof(Body) * bodies_.capacity() + sizeof(Cold) * cold_.capacity() +
                        sizeof(std::uint32_t) * order_.capacity() +
                        sizeof(ParticleId) * ids_.capacity() + cells_.memoryBytes() +
                        queue_.memoryBytes() + obstacles_.memoryBytes() + rate_.memoryBytes() +
                        sizeof(Slide) * slide_.capacity();
    for (const Level& level : upper_)
        bytes += level.cells.memoryBytes();
    // An unordered_map node holds the key, the value and the next pointer; the table one
    // pointer per bucket.
    bytes += overlapContact_.size() * (sizeof(std::uint64_t) + sizeof(double) + sizeof(void*)) +
             overlapContact_.bucket_count() * sizeof(void*);
    return bytes;
}

}  // namespace psb::exact
