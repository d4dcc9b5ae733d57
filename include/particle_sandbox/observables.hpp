#pragma once
/// \file
/// The observables of a hard-disc gas, measured over a window of simulated time that the caller
/// opens and closes, each with its standard error by block averaging: temperature, pressure (from
/// the collision virial and from the walls), compressibility factor, the radial distribution
/// function g(r) and its contact value, the mean-squared displacement and the velocity
/// autocorrelation with the diffusion coefficient from each, the collision rate per particle and
/// the mean free path, beside what theory predicts for them (hard_disc_theory.hpp).
///
/// ## Conventions
/// Two dimensions: a pressure is a force per length of wall (N/m), an area is in m².
///
/// **Length and area: those of the box the centres move in.** A disc's centre comes no closer to
/// a wall than its radius r, so the centres move in A′ = (w − 2r)(h − 2r), whose perimeter is
/// L′ = 2(w − 2r + h − 2r) (r the mean radius: exact for equal discs). Every pressure is per
/// length of L′, every density N / A′, and Z = P A′ / (N kT). Why: with this one convention
/// the wall pressure and the virial pressure are the same quantity (the virial theorem for the
/// walls: each wall's hits happen at its centres' line, so the walls' virial is −2 P A′
/// exactly), and an ideal gas gives P A′ = N kT whatever the discs' size. With the box's own
/// perimeter and area the two would differ by O(r / w) (4 % at N = 400, φ = 0.5).
///
/// **Temperature** kT = ⟨Σ ½ m |v|²⟩ / N (two translational degrees of freedom per particle,
/// none removed: walls do not conserve momentum), in joules. In a world whose discs turn, the
/// rotational temperature kT_rot = ⟨Σ ½ I ω²⟩ · 2 / N_turning (one degree of freedom each).
///
/// **Virial pressure** P = (N kT + Σ r_ij·J_ij / (2 T)) / A′, so Z = 1 + Σ r_ij·J_ij / (2 T N kT)
/// whatever the area: the sum runs over the pair
/// collisions of the window (T seconds), r_ij the centre of i minus that of j at contact and J_ij
/// the impulse j gave i (World::setMeasureVirial, StepCounters::pairVirial). Exact mode: the
/// impulses at the instant of contact; discrete and substep modes: the contact impulses of the
/// resolve stage, at the (overlapping) positions it finds. Only pair collisions count, so it is
/// not reported with gravity or fixed obstacles (whose forces would need their own virial).
///
/// **Wall pressure** the walls' normal impulse (StepCounters::wallImpulse) per second per L′;
/// only with walls and without gravity.
///
/// **Errors**: the window is cut into blocks of equal numbers of samples (between
/// kBlocks and 2 kBlocks of them: when they reach 2 kBlocks, neighbours merge); a value's error is
/// the standard error of its block values, sd / √B. Blocks must be longer than the quantity's
/// correlation time (a few mean free times for the pressure) for it to be honest: a window of a
/// few hundred collisions per particle is. A window with fewer than kMinBlocks full blocks reports
/// no error (and says so in `notes`).
///
/// **g(r)** counts pair distances up to `pairRange` (half the box's shorter side by default) in
/// bins of `pairBinWidth`, normalised by what the same number of uniformly placed centres in the
/// centres' box A′ would give (the rectangle's isotropic set covariance, so the box's edges do not
/// pull g(r) down at large r). Its **contact value** is the quadratic least-squares fit to the
/// bins in [σ, 1.2 σ], evaluated at σ = 2r (equal discs only). The collision virial counts
/// contacts per area A′, g(r) per pair measure of the rectangle, so in a box with walls
/// Z = 1 + 2 φ′ g(σ) γ̄(σ)/A′ with φ′ = N π r² / A′ and γ̄(σ)/A′ = 1 − 2σ(a + b)/(π a b) (the
/// centres' box a × b); a periodic box has no such factor.
///
/// **MSD and VACF** over lag times 0, Δ, 2Δ, … up to `maxLag`, Δ the time between state samples,
/// averaged over particles and over time origins (a new origin every `originEvery` state
/// samples). D from the MSD: the least-squares slope of MSD(t) over [maxLag/2, maxLag], over 4
/// (Einstein: MSD → 4 D t in 2-D). D from the VACF: ½ ∫₀ᵗ C(s) ds (Green–Kubo, trapezoids),
/// averaged over the same t, so that both estimate the same D(t). The VACF's trapezoids need
/// Δ well below the mean free time (suggestedObservablesSettings takes a quarter of Enskog's).
/// Displacements are taken from the positions as they are (in a box with walls a particle never
/// wraps).
///
/// **Collision rate** per particle: 2 × pair collisions / (N T); the **wall collision rate** the
/// box's wall rebounds per second (StepCounters::wallCollisions / T). **Mean free path** the mean
/// speed ⟨|v|⟩ over the collision rate. Beside them, Enskog's with Henderson's g(σ), at the
/// measured kT and ρ = N / A′ (equal discs and masses only).
///
/// ## Cost
/// A world whose virial is not measured pays nothing and steps bit-identically to one that never
/// heard of observables. sample() itself reads only the counters and the clock; the particles are
/// read (in the exact mode that costs a sync of every particle) every `stateEvery` samples, and
/// g(r) takes all pairs within `pairRange` every `pairEvery` state samples.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace psb {

class World;

/// A measured value and its standard error; NaN for what was not measured (value) or has no
/// error (error).
struct Measured {
    double value = std::numeric_limits<double>::quiet_NaN();
    double error = std::numeric_limits<double>::quiet_NaN();
    [[nodiscard]] bool valid() const { return value == value; }
    [[nodiscard]] bool hasError() const { return error == error; }
};

/// How a window samples. Defaults: every sample reads the particles, no g(r), no MSD or VACF.
struct ObservablesSettings {
    /// Read the particles (temperature, speeds, MSD, VACF, g(r)) every this many samples, >= 1.
    std::uint32_t stateEvery = 1;
    /// A g(r) snapshot every this many state samples; 0 for none.
    std::uint32_t pairEvery = 0;
    /// g(r) up to this distance, metres; 0: half the box's shorter side.
    double pairRange = 0.0;
    /// g(r)'s bin width, metres; 0: σ / 50 for equal discs, else pairRange / 1000.
    double pairBinWidth = 0.0;
    /// MSD and VACF up to this many state samples of lag; 0 for none.
    std::uint32_t maxLag = 0;
    /// A new time origin every this many state samples; 0: maxLag / 2 (at least 1).
    std::uint32_t originEvery = 0;
};

/// What a window measured.
struct ObservablesResult {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    std::size_t particles = 0;
    double duration = 0.0;      ///< simulated seconds the window spans
    std::uint64_t samples = 0;  ///< intervals between samples
    std::uint64_t stateSamples = 0;
    int blocks = 0;              ///< full blocks the errors come from
    double blockDuration = 0.0;  ///< s, each
    double area = 0.0;           ///< A′, m² (the convention above)
    double perimeter = 0.0;      ///< L′, m
    double density = 0.0;        ///< N / A′, 1/m² (the centres' density)
    /// The box's packing fraction Σ π r² / (w h) (as a generate block's packing_fraction).
    double packingFraction = 0.0;
    /// Equal discs and masses: the diameter σ (m) and the mass (kg); NaN else.
    double sigma = kNaN, mass = kNaN;

    Measured temperature;            ///< kT, J
    Measured rotationalTemperature;  ///< kT_rot, J (worlds whose discs turn)
    Measured pressureVirial;         ///< N/m
    Measured pressureWalls;          ///< N/m (walls, no gravity)
    Measured compressibilityFactor;  ///< Z = P_virial A′ / (N kT)
    Measured contactValue;           ///< g(σ) extrapolated from g(r)
    Measured collisionRate;          ///< pair collisions per particle per second
    Measured wallCollisionRate;      ///< wall rebounds per second, the whole box's (walls)
    Measured meanFreePath;           ///< m
    Measured diffusionMsd;           ///< m²/s
    Measured diffusionVacf;          ///< m²/s

    /// Theory at the measured kT and the box's packing fraction and density N / (w h)
    /// (hard_disc_theory.hpp): Henderson's Z and g(σ), Enskog's collision rate (1/s), mean free
    /// path (m) and D (m²/s); NaN unless the discs are equal. Why the box's density and not the
    /// centres': the bulk between the walls is less dense than N / A′ (the discs pack against
    /// the walls in layers), and measured, N / (w h) is the nearer: 1000 exact discs at 0.3 gave
    /// Z 0.7 % above Henderson's at the box's φ and 2.9 % below it at the centres'.
    double hendersonZ = kNaN, hendersonContact = kNaN;
    /// Liu's simulation-based Z for the fluid (hard_disc_theory.hpp); NaN beyond φ 0.70.
    double liuZ = kNaN;
    double enskogCollisionRate = kNaN, enskogMeanFreePath = kNaN, enskogDiffusion = kNaN;

    /// g(r): bin centres (m) and values; empty without snapshots.
    std::vector<double> pairR, pairG;
    /// Lag times (s), MSD (m², per particle) and VACF ⟨v(0)·v(t)⟩ (m²/s²); empty without.
    std::vector<double> lagTime, msd, vacf;
    /// Why a value is missing or in doubt, one sentence each.
    std::vector<std::string> notes;
};

/// Settings for a gas in `world` sampled every `sampleInterval` seconds (the caller's step),
/// chosen from Enskog's predictions (hard_disc_theory.hpp) for its density and temperature: state
/// samples a quarter of a mean free time apart (at least one sample), MSD and VACF to twenty mean
/// free times or the time a particle takes to diffuse an eighth of the box, whichever is shorter,
/// and g(r) snapshots rare enough that counting pairs costs about 3 % of an exact step's time.
/// `correlations` and `pairs` switch those parts on. A world that is not a gas of equal discs
/// (or has no motion) gets state samples every sample and lags of 64 samples.
[[nodiscard]] ObservablesSettings suggestedObservablesSettings(const World& world,
                                                               double sampleInterval,
                                                               bool correlations, bool pairs);

/// A window of measurement: open() on a world, sample() after each step (or at any steady
/// cadence), close() at the end. The world must be the same one throughout (the window keeps no
/// pointer to it); particles added or removed during the window stop the MSD and VACF (noted).
class ObservablesWindow {
  public:
    /// Blocks the errors come from: between kBlocks and 2 kBlocks.
    static constexpr int kBlocks = 16;
    /// Fewer full blocks than this: no errors.
    static constexpr int kMinBlocks = 8;

    explicit ObservablesWindow(const ObservablesSettings& settings = {});
    ~ObservablesWindow();
    ObservablesWindow(ObservablesWindow&&) noexcept;
    ObservablesWindow& operator=(ObservablesWindow&&) noexcept;

    /// Starts the window at the world's present state: turns on its virial counter
    /// (World::setMeasureVirial) and takes the first sample. Throws InvalidArgument for an empty
    /// world or settings out of range (stateEvery 0, a negative or non-finite range or width).
    void open(World& world);
    /// Takes a sample of `world` (the one opened) after its latest steps; a sample at the same
    /// time as the last adds nothing.
    void sample(const World& world);
    /// What the window has measured so far.
    [[nodiscard]] ObservablesResult result() const;
    /// Takes a last sample, stops the world's virial counter and returns the result.
    ObservablesResult close(World& world);
    [[nodiscard]] bool isOpen() const;

  private:
    struct State;
    /// Reads the particles: temperature, speeds, MSD and VACF, and g(r) when due.
    void readState(const World& world);
    ObservablesSettings settings_;
    std::unique_ptr<State> state_;
};

}  // namespace psb
