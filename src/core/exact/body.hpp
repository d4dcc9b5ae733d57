#pragma once
// The exact stepper's records: what it keeps per particle (Body, what a neighbour's prediction
// reads; Cold, what only the particle's own events read), the events it schedules, where a
// particle is at a time and how it moves there (Motion, Gravity), a sliding contact (Slide) and
// a rotation (Turn).
//
// Memory. Events come in time order, which is random in space, so at 10^5 particles nearly
// every particle an event touches is a cache miss. What an event reads about a neighbour is one
// 64-byte line (Body), what it reads about its own particle another (Cold); particles are
// re-sorted into cell order every kResortEvery·N events (indices only: nothing physical
// changes), a neighbourhood's members are gathered and prefetched before they are tested, and
// the particle of the likely next event is prefetched while this one is handled.

#include <cstdint>
#include <vector>

namespace psb::exact {

// What a particle's collision key holds (its cell key always holds a cell move).
enum class Kind : std::uint8_t { None, Pair, Wall, Obstacle, Slide, Recheck, Roll };

// What an event and a neighbour's prediction read, in one 64-byte line.
struct alignas(64) Body {
    double x, y;          // centre at time t, metres
    double vx, vy;        // m/s
    double t;             // time of the last velocity change (or rebuild), seconds
    double r;             // radius
    double nextColl;      // time of its scheduled collision event (see scanCells)
    std::uint32_t count;  // bumped at every velocity change
    std::uint32_t flags;  // kHeld, kJammed, ... (below)
};
inline constexpr std::uint32_t kHeld = 1;               // kinematic: infinite mass
inline constexpr std::uint32_t kJammed = 2;             // passes through held particles (jam guard)
inline constexpr std::uint32_t kPlacedOverlapping = 4;  // in a pair of PlacedContacts
inline constexpr std::uint32_t kAsleep = 8;             // at rest: no velocity, no acceleration
inline constexpr std::uint32_t kRestX = 16;         // no acceleration along x (on a wall, pinned)
inline constexpr std::uint32_t kRestY = 32;         // no acceleration along y
inline constexpr std::uint32_t kSliding = 64;       // on a segment's face: Slides holds how
inline constexpr std::uint32_t kProvisional = 128;  // asleep until its recheck (resting.hpp)
// A disc that turns, in a world with rough contacts, on the face it slides on (kSliding) or the
// one wall it rests on (kRestX or kRestY): it slips or rolls (rolls.hpp); Slides holds its
// acceleration along the surface and the end of its slip, its Turn (Rolls) its angular
// acceleration. Also a disc that does not turn on the wall it rests on: it slides under kinetic
// friction until it stops (slipEnds).
inline constexpr std::uint32_t kRolling = 256;
// Wider than the box both ways (or with no room along either axis: kNoRoom): it sits on the
// box's centre and takes no impulse, as fixed as a held particle. A held particle passes
// through it as through another held one: neither can give way, so their contact would be met
// again at the same instant without end.
inline constexpr std::uint32_t kPinned = 512;
inline constexpr std::uint32_t kImmovable = kHeld | kPinned;
// A particle sliding on a segment's face (kSliding; slides.cpp): which
// segment, and its constant acceleration along the face (gravity's share along it less the
// kinetic friction, or none where static friction holds it). A disc that rolls (kRolling) keeps
// here its acceleration along the face or wall and when its slip ends (rolls.hpp).
struct Slide {
    std::uint32_t obstacle = 0;
    double ax = 0.0, ay = 0.0;
    double slipEnds = 0.0;  // kRolling: the slip-to-roll instant (infinity: none ahead)
};
// A particle's rotation (kept only in a world that keeps rotation): its angle at time t (on the
// stepper's clock), its angular velocity then, its spin weight 1/k (0: fixed) and its angular
// acceleration since t. Rough impulses change omega; between two of them the angular
// acceleration is zero, except while the disc slips or rolls on a surface (kRolling), where
// the contact's friction makes it constant: the angle is then a parabola in time.
struct Turn {
    double angle;
    double t;
    double omega;
    double q;
    double alpha = 0.0;
};
// Where a particle is at a time, and how it moves there (gravity only).
struct Motion {
    double x, y, vx, vy, ax, ay;
};
// The gravity particles fall under (m/s²); `on`: it is not zero.
struct Gravity {
    double x = 0.0, y = 0.0;
    bool on = false;
};
struct Event {
    double time;
    std::uint32_t partner;       // pair: the other particle; obstacle: its index
    std::uint32_t partnerCount;  // pair: its counter when predicted
    Kind kind;
    std::int8_t side;  // wall: 0..3 (left, right, top, bottom)
};

// What only the particle's own events read, in one line.
struct alignas(64) Cold {
    Event coll;              // its next collision (pair or wall)
    double m;                // mass
    std::int64_t kx, ky;     // cell coordinates
    std::int8_t cellSide;    // the face its next cell event crosses: -x, +x, -y, +y
    bool pinX, pinY;         // no room between the walls along this axis (kNoRoom)
    std::uint8_t level;      // its size class (grid.cpp, "Size levels")
    std::uint32_t heldHits;  // collisions with held particles this step (jam guard)
    double w;                // inverse mass, 0 = held
};
static_assert(sizeof(Cold) == 64);

// Follows a renumbering of the particles (a sort into cell order, grid.hpp): the element of
// particle i moves to to[i].
template <typename T>
void renumber(std::vector<T>& v, const std::vector<std::uint32_t>& to) {
    std::vector<T> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
        out[to[i]] = v[i];
    v.swap(out);
}

}  // namespace psb::exact
