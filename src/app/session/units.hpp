#pragma once
// Numbers for people: three significant figures with an SI prefix for a simple unit
// ("4.04 MJ", "1.20 mm", "9.81 m/s^2"), digits grouped by thousands for a compound one
// ("40 390 kg m/s"), and the accuracy of a conserved quantity in words
// ("energy kept to 1 part in 10¹⁴"). No "4.039e+06" reaches the screen, except where a person
// types the number back (plainNumber). Every number the app writes for people comes from here.

#include <string>

#include <particle_sandbox/math.hpp>

namespace psb::app {

/// `value` in `unit` with an SI prefix (k, M, G, T, P, E; m, µ, n, p, f, a) chosen so the
/// number is in [1, 1000), three significant figures; zero is "0 unit"; beyond the prefixes a
/// power of ten ("1.03 × 10²⁴ J"). For units a prefix would garble ("kg m/s", "m/s^2") pass
/// `prefix` false: the digits are then grouped by thousands ("12 300 kg m/s"), small values
/// keep three significant figures ("0.00123 kg m/s"), and from a billion up or below a
/// millionth it is a power of ten.
[[nodiscard]] std::string quantity(double value, const std::string& unit, bool prefix = true);

/// `value` with up to `significant` figures, trailing zeros dropped, as printf's %g writes it
/// ("0.25", "9.81", "1e+06"): for a number a person types back or reads beside one they typed
/// (a particle's fields, a refused edit, a settings file's message, a window's length in
/// seconds), where prefixes and grouped digits would not read back. "-0" is "0".
[[nodiscard]] std::string plainNumber(double value, int significant = 6);

/// A number in a field a person types into (the values table's cells, the Selected particle
/// section's fields): as the readouts write the same quantity without a prefix, three
/// significant figures with their trailing zeros (2.5 m/s is "-2.50" in the field as on the
/// card, the labels and the momentum's column; 1 kg is "1.00" as the total's "4.00"), but
/// never grouped by thousands ("1230") nor a power of ten in words ("1.23e-07"), so that it
/// reads back as typed. A field being typed in keeps what is typed.
[[nodiscard]] std::string fieldNumber(double value);

/// A vector's signed components as quantity() writes them without a prefix, in brackets:
/// "(2.00, 0)", "(-2.50, 1.00)" (the unit goes after, once).
[[nodiscard]] std::string components(const Vec2& v);

/// "[x, y]" for a message: each at most three figures (plainNumber), or with `decimals` >= 0
/// that many decimals ("[670.00, 350.00]"), the space after the comma a no-break space, so
/// that a message wrapped at its spaces never breaks a vector ("[-1, / 0]").
[[nodiscard]] std::string pair(double x, double y, int decimals = -1);

/// A measured `value` and its uncertainty `error` in `unit` (no prefix, digits grouped): the
/// error to two significant figures, the value to the same decimal place, "12.40 ± 0.26 N/m"
/// (not "12.4 ± 0.257 N/m", an error written to more digits than the value), "12 190 ± 350".
[[nodiscard]] std::string withError(double value, double error, const std::string& unit);

/// A relative change (|change| / reference) in words: "kept to 1 part in 10¹⁴" (the power
/// rounded down), "kept exactly" below 10^-15 (rounding of the sums), "changed by 2.3 %" at a
/// tenth of a percent or more; "not measured" for NaN.
[[nodiscard]] std::string keptWords(double relativeChange);

/// The deepest overlap between particles (metres) in words, for a scene whose typical particle
/// has radius `typicalRadius`: "Particles overlap by up to 1.20 mm"; "No particles overlap" at
/// 0, and "(beyond rounding)" added below 10^-9 of the radius, where it is the rounding of
/// the arithmetic (touching discs of the exact mode) and not worth a number in attometres.
[[nodiscard]] std::string overlapWords(double overlap, double typicalRadius);

}  // namespace psb::app
