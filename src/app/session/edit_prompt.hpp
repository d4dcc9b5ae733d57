#pragma once
// Editing the selected particle from the keyboard, without SDL (the app feeds it the text of
// SDL_TEXTINPUT events and the Tab, Backspace, Enter and Esc keys).
//
// The prompt holds six text fields, mass (kg), radius (m), vx and vy (m/s), the angular
// velocity omega (rad/s) and the inertia factor k (I = k m r²), filled with the particle's
// values when it opens. Values are shown and typed in the user's axes (Axes: with y up, vy
// upward and omega counterclockwise-positive) and set in the world's. Tab moves to the next field;
// the first character typed into a field just entered replaces its text (as if it were selected).
// Enter hands the six texts to checkEdit, which checks all of them: the edit it passes is what
// the world's owner writes (particle_edit.hpp), all of it or nothing.
//
// What the checks accept, so that an edit can never put the world in a state it would refuse
// from a scene file:
// - every field a finite decimal number (NaN, inf, "12kg" and empty fields are refused);
// - mass a positive normal double (World::setMass's rule), radius > 0;
// - speed at most kMaxEditSpeedBoxes box sizes per second, and a finite kinetic energy; the
//   same for the rim's speed |omega| r and the rotational energy;
// - k from 0.001 to 1 (World::setInertiaFactor's rule); a fixed-rotation particle only omega 0;
// - a radius that fits the box when walls are on. A disc that would then reach past a wall is
//   moved inward just enough (the wall stage would push it there at the next step anyway);
// - no new overlap: a disc that grows (or was moved inward) may not overlap a neighbour more
//   than it did before. Such an edit is refused with the neighbour's position, not resolved by
//   moving particles the user did not touch.
// A refusal changes nothing and says which field is wrong and why.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

enum class EditField { Mass, Radius, Vx, Vy, Omega, Inertia };
/// One value of a particle, for edits of a single field (the control panel's tables).
enum class ParticleField : std::uint8_t { X, Y, Vx, Vy, Mass, Radius, Omega, Inertia };
inline constexpr int kEditFields = 6;

/// Fastest velocity an edit may give, in box sizes (the larger side) per second: beyond this a
/// particle crosses the box many times in one step.
inline constexpr double kMaxEditSpeedBoxes = 1000.0;

/// "mass", "radius", "vx", "vy", "omega", "k".
[[nodiscard]] const char* fieldName(EditField f);
/// "x", "y", "vx", "vy", "mass", "radius", "omega", "k".
[[nodiscard]] const char* fieldName(ParticleField f);
/// "kg", "m", "m/s", "rad/s", "(I = k m r^2)".
[[nodiscard]] const char* fieldUnit(EditField f);
class EditPrompt {
  public:
    /// Longest text a field takes, characters.
    static constexpr std::size_t kMaxLength = 32;

    /// Opens the prompt on `p`, its fields holding p's values, the mass field active.
    void open(const Particle& p, const Axes& axes = {});
    void close();
    [[nodiscard]] bool active() const { return active_; }
    /// The particle being edited (null when closed).
    [[nodiscard]] ParticleId target() const { return target_; }

    void nextField();
    void previousField();
    /// Adds printable ASCII characters of `text` to the active field (others are dropped).
    void type(std::string_view text);
    void backspace();

    [[nodiscard]] EditField field() const { return field_; }
    [[nodiscard]] const std::string& text(EditField f) const {
        return texts_[static_cast<std::size_t>(f)];
    }
    [[nodiscard]] const std::array<std::string, kEditFields>& texts() const { return texts_; }
    /// Why the last Enter was refused; empty when it was not.
    [[nodiscard]] const std::string& error() const { return error_; }
    void setError(std::string why) { error_ = std::move(why); }

  private:
    bool active_ = false;
    bool fresh_ = false;  ///< the active field was just entered: typing replaces its text
    ParticleId target_;
    EditField field_ = EditField::Mass;
    std::array<std::string, kEditFields> texts_;
    std::string error_;
};

/// What an edit sets: a particle's mass, radius, position, velocity, angular velocity and
/// inertia factor.
struct EditedValues {
    double mass = 1.0;
    double radius = 1.0;
    Vec2 position = Vec2::Zero();
    Vec2 velocity = Vec2::Zero();
    double omega = 0.0;
    double inertiaFactor = kDefaultInertiaFactor;
};
/// `p`'s values, as an edit that changes nothing would set them.
[[nodiscard]] EditedValues valuesOf(const Particle& p);

/// An edit of one particle, checked (see the top of this file): what to write, or why not.
struct CheckedEdit {
    ParticleId id;
    /// Why the edit is refused (which field is wrong and why); empty: it passed.
    std::string refusal;
    /// What to write: the values asked for, the position moved inward to stay inside the walls.
    EditedValues values;
    Vec2 wanted = Vec2::Zero();  ///< the position asked for
    [[nodiscard]] bool passed() const { return refusal.empty(); }
};

/// Parses and checks `texts` (mass, radius, vx, vy, omega, k, typed in `axes`) as an edit of
/// particle `id` of `world`. Never throws for bad text or values.
[[nodiscard]] CheckedEdit checkEdit(const World& world, ParticleId id,
                                    const std::array<std::string, kEditFields>& texts,
                                    const Axes& axes = {});
/// One field of particle `id` set from `text`, checked as checkEdit checks (a position must
/// also lie inside the walls).
[[nodiscard]] CheckedEdit checkValue(const World& world, ParticleId id, ParticleField field,
                                     std::string_view text, const Axes& axes = {});
/// The checks both edits share, of particle `id` of `world` given `wanted`; `axes`: how its
/// messages show the values.
[[nodiscard]] CheckedEdit check(const World& world, ParticleId id, const EditedValues& wanted,
                                const Axes& axes = {});

}  // namespace psb::app
