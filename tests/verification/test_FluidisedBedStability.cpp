// Verification problem 12 (physics.md sections 4 and 7): the linear stability of a uniformly
// fluidised bed. The P0 sand held fluidised at n0 = 0.452 by its equilibrium flux q(n0) (problem
// 7's expanded bed) starts with a porosity wave n0 + 1e-3 sin(k (z - z_filter)); the wave's
// growth rate and its speed up the column, read from the run by fitting a sine to the rows'
// porosity at each output, are compared with the dispersion relation of quicksand's own
// equations (physics/FluidisedBedStability.hpp): a kinematic wave rising at c = phi0 dq/dn,
// damped at D k^2 by the front diffusion D = h c_n / 4 and grown by the inertia at D_i k^2 (600
// times smaller: the grid decides, section 7's finding). Two wavelengths and two cell sizes;
// tolerance 10 % on the growth and on the speed, with guards near what is reached. The discrete
// wave is slower than the continuum's by about (kh)^2 / 3, second order in the cell: at 8 cells a
// wavelength that is 20 %, so there the speed is checked by its order of convergence instead.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "VerificationCase.hpp"
#include "core/Constants.hpp"
#include "physics/FluidisedBedStability.hpp"
#include "physics/FrontDiffusion.hpp"
#include "physics/ParticlePhase.hpp"

using namespace qs;
using namespace qs::test;

namespace {

constexpr double kN0 = 0.452, kAmplitude = 1e-3;

/// The least-squares slope of y against t, and its r^2 where asked.
double slopeOf(const std::vector<double>& t, const std::vector<double>& y, double* r2) {
    const double n = static_cast<double>(t.size());
    double st = 0, sy = 0, stt = 0, sty = 0, syy = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        st += t[i]; sy += y[i]; stt += t[i] * t[i]; sty += t[i] * y[i]; syy += y[i] * y[i];
    }
    const double b = (n * sty - st * sy) / (n * stt - st * st);
    if (r2) {
        const double a = (sy - b * st) / n, ssTot = syy - sy * sy / n, ssRes = syy - a * sy - b * sty;
        *r2 = ssTot > 0 ? 1 - ssRes / ssTot : 1;
    }
    return b;
}

struct WaveFit {
    double growth = 0;      ///< 1/s, d ln A / dt
    double speed = 0;       ///< m/s, the crests' speed up the column
    double r2 = 0;          ///< of ln A against t
    int outputs = 0;
    double firstAmplitude = 0, lastAmplitude = 0;
};

/// A sine of wavenumber k fitted to the rows' porosity over [z0, z1] at each output:
/// n = m + a sin(k s) + b cos(k s) = m + A sin(k s + theta), s = z - zFilter; then ln A and the
/// unwrapped theta against t (crests rise at -dtheta/dt / k).
WaveFit fitWave(const CaseRun& run, double k, double zFilter, double z0, double z1) {
    std::vector<double> t, lnA, theta;
    for (std::size_t o = 0; o < run.profiles.size(); ++o) {
        // normal equations of (1, sin, cos)
        double M[3][3] = {}, r[3] = {};
        for (const auto& row : run.profiles[o]) {
            if (row.solidCount == 0 || row.z < z0 || row.z > z1) continue;
            const double f[3] = {1, std::sin(k * (row.z - zFilter)), std::cos(k * (row.z - zFilter))};
            for (int i = 0; i < 3; ++i) {
                r[i] += f[i] * row.porosity;
                for (int j = 0; j < 3; ++j) M[i][j] += f[i] * f[j];
            }
        }
        // 3 x 3 by Cramer
        auto det = [](double A[3][3]) {
            return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                   A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
        };
        const double d = det(M);
        double x[3];
        for (int c = 0; c < 3; ++c) {
            double Mc[3][3];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) Mc[i][j] = j == c ? r[i] : M[i][j];
            x[c] = det(Mc) / d;
        }
        t.push_back(run.series[o].time);
        lnA.push_back(std::log(std::hypot(x[1], x[2])));
        double th = std::atan2(x[2], x[1]);
        while (!theta.empty() && th - theta.back() > kPi) th -= 2 * kPi;
        while (!theta.empty() && th - theta.back() < -kPi) th += 2 * kPi;
        theta.push_back(th);
        if (std::getenv("QS_WAVE_TRACE"))
            std::printf("  t %.2f  A %.4e  theta %.4f  mean %.5f\n", t.back(), std::exp(lnA.back()), th, x[0]);
    }
    auto slope = [&](const std::vector<double>& y, double* r2) { return slopeOf(t, y, r2); };
    WaveFit fit;
    fit.growth = slope(lnA, &fit.r2);
    fit.speed = -slope(theta, nullptr) / k;
    fit.outputs = static_cast<int>(t.size());
    fit.firstAmplitude = std::exp(lnA.front());
    fit.lastAmplitude = std::exp(lnA.back());
    return fit;
}

struct Outcome {
    double growthError = 0, speedError = 0;  ///< relative to the closed form
    double growth = 0, expectedGrowth = 0;   ///< 1/s
    /// the rows' porosity rms about their mean over the bed's inside (all wavelengths: the wave
    /// and whatever the points' own discreteness seeds), at the start and at the end
    double rmsStart = 0, rmsEnd = 0;
};

/// The rms of the rows' porosity about its mean over [z0, z1].
double porosityRms(const std::vector<CellRow>& rows, double z0, double z1) {
    double sum = 0, sum2 = 0;
    int count = 0;
    for (const auto& r : rows) {
        if (r.solidCount == 0 || r.z < z0 || r.z > z1) continue;
        sum += r.porosity;
        sum2 += r.porosity * r.porosity;
        ++count;
    }
    const double mean = sum / count;
    return std::sqrt(std::max(0.0, sum2 / count - mean * mean));
}

/// The bed the wave runs in: by default problem 7's P0 sand expanded to n0 = 0.452, 0.298 m of
/// it, 6 s. `material` changes the sand first (its grains, the particle phase, the front
/// diffusion's alpha): the bed is fluidised at its own q(n0), and the closed form follows.
struct WaveBed {
    double n0 = kN0;
    double thickness = 48 * 0.0062;  ///< m: room for the wave to rise
    double end = 6.0, outputInterval = 0.25;  ///< s
    std::function<void(MaterialConfig&)> material;
    /// a lateral wave n0 + A cos(k x) in a 2D bed half a wavelength wide (its smooth walls are
    /// the cosine's planes of symmetry) instead of the vertical one
    bool lateral = false;
};

/// The case of the wave of `wavelength` on cells of `cellSize` in `spec`'s bed, run.
CaseRun runWaveCase(double wavelength, double cellSize, const WaveBed& spec) {
    CaseConfig c = loadVerificationCase("bed_expansion");
    if (spec.material) spec.material(c.materials.front());
    const double n0 = spec.n0;
    const auto flux = closed::SuspensionFlux::of(c, c.material("sand"));
    const double q0 = flux.equilibriumFlux(n0);
    c.grid.cellSize = cellSize;
    c.materials.front().porosity = n0;
    c.initial.state = InitialState::Fluidised;
    c.initial.stress = InitialStress::Zero;
    c.initial.filterVelocity = q0;
    c.gate.flux = q0;
    c.column.chamberHeight = 4 * 0.0062;                 // whole cells of both sizes
    c.layers.front().thickness = spec.thickness;
    c.column.waterLevel = c.sandTop() + 8 * 0.0062;
    c.column.overflowLevel = c.column.waterLevel;
    c.column.top = c.column.waterLevel + 2 * 0.0062;
    c.monitors.front().elevation = c.filterLevel() + 0.5 * c.layers.front().thickness;
    if (spec.lateral) {
        c.grid.dimension = 2;
        c.grid.width = wavelength / 2;
    }
    c.initial.porosityWave = {true, kAmplitude, wavelength, spec.lateral};
    c.time.end = spec.end;
    c.time.outputInterval = spec.outputInterval;
    return runConfig(c);
}

/// Runs the wave of `wavelength` on cells of `cellSize` and compares it with the closed form.
Outcome runWave(double wavelength, double cellSize, const WaveBed& spec = {}) {
    const CaseRun run = runWaveCase(wavelength, cellSize, spec);
    const CaseConfig& c = run.config;
    const double n0 = spec.n0;
    const auto flux = closed::SuspensionFlux::of(c, c.material("sand"));

    const auto& sand = c.material("sand");
    closed::FluidisedBed bed;
    bed.suspension = flux;
    bed.porosity = n0;
    bed.maxPacking = 1 - sand.minPorosity;
    const DragLaw drag{c.liquid.viscosity, c.liquid.density};
    bed.diffusivity = frontDiffusivity(drag, PermeabilityLaw::from(sand), sand.grainDensity, c.gravity,
                                       sand.maxPorosity, c.grid.cellSize, sand.frontDiffusion);
    if (sand.frontThreshold > 0) {
        // the diffusion fades as (h |grad phi| / s)^2: on a wave of amplitude A, its first harmonic
        // feels D (h k A / s)^2 3/4
        const double r = cellSize * 2 * kPi / wavelength * kAmplitude / sand.frontThreshold;
        bed.diffusivity *= std::min(1.0, 0.75 * r * r);
    }
    if (sand.particlePhase == ParticlePhaseModel::FoscoloGibilaro)
        bed.particleModulus =
            FoscoloGibilaro{sand.particleGrainSize, sand.grainDensity, c.liquid.density, c.gravity}.modulus(n0);
    const double k = 2 * kPi / wavelength;
    const auto s = bed.verticalGrowth(k);
    const double expectedGrowth = s.real(), expectedSpeed = -s.imag() / k;
    // the rows the initial wave still holds at the end (it leaves the filter's side at c), less
    // two cells at either end (the diffusion does not act at the filter nor in the top two rows)
    const double z0 = c.filterLevel() + expectedSpeed * c.time.end + 2 * cellSize;
    const double z1 = c.sandTop() - 3 * cellSize;
    const WaveFit fit = fitWave(run, k, c.filterLevel(), z0, z1);
    Outcome out;
    out.growth = fit.growth;
    out.expectedGrowth = expectedGrowth;
    out.rmsStart = porosityRms(run.profiles.front(), c.filterLevel() + 3 * cellSize, c.sandTop() - 3 * cellSize);
    out.rmsEnd = porosityRms(run.profiles.back(), c.filterLevel() + 3 * cellSize, c.sandTop() - 3 * cellSize);
    out.growthError = (fit.growth - expectedGrowth) / std::abs(expectedGrowth);
    out.speedError = (fit.speed - expectedSpeed) / expectedSpeed;
    std::printf("lambda %.3f m, h %.4f m: growth %.4f 1/s (closed form %.4f: -D k^2 %.4f - K/B k^2 %.4f + D_i k^2 "
                "%.2e; %+.1f %%, ln A r^2 %.4f), speed %.4e m/s (closed form %.4e, %+.2f %%); A %.2e -> %.2e over %d "
                "outputs\n",
                wavelength, cellSize, fit.growth, expectedGrowth, -bed.diffusivity * k * k,
                -bed.particleModulus / bed.base().dragCoefficient * k * k,
                bed.base().inertialDiffusivity * k * k, 100 * out.growthError, fit.r2, fit.speed, expectedSpeed,
                100 * out.speedError, fit.firstAmplitude, fit.lastAmplitude, fit.outputs);
    std::printf("  the porosity's rms over the bed: %.3e at the start, %.3e at %.2f s\n", out.rmsStart, out.rmsEnd,
                c.time.end);
    return out;
}

/// The wave of `wavelength` on 6.2 and 3.1 mm cells: the growth within 10 % on both, the speed
/// within 10 % where the wave spans 16 cells or more, and the speed's error falling at second
/// order in the cell size (the discrete wave's dispersion, (kh)^2 / 3 to leading order: -20 %,
/// -5.2 % and -1.3 % at 8, 16 and 32 cells a wavelength).
void expectWaveOnTwoCellSizes(double wavelength, double growthGuard, double speedGuardFine) {
    const Outcome coarse = runWave(wavelength, 0.0062), fine = runWave(wavelength, 0.0031);
    for (const Outcome& o : {coarse, fine}) {
        EXPECT_LT(std::abs(o.growthError), 0.10);
        EXPECT_LT(std::abs(o.growthError), growthGuard);  // a guard near what is reached
    }
    if (wavelength / 0.0062 >= 16 - 1e-9) {
        EXPECT_LT(std::abs(coarse.speedError), 0.10);
    }
    EXPECT_LT(std::abs(fine.speedError), 0.10);
    EXPECT_LT(std::abs(fine.speedError), speedGuardFine);
    const double order = std::log2(coarse.speedError / fine.speedError);
    EXPECT_NEAR(order, 2.0, 0.15) << "the speed's errors " << coarse.speedError << " and " << fine.speedError;
    std::printf("the speed's error falls at order %.2f\n", order);
}

}  // namespace

// 8 and 16 cells a wavelength (2026-12-07, both schemes: growth +2.0 % and +1.0 %; speed
// -19.9 % and -5.3 %, order 1.91). Semi-implicit only since the particle phase's tests came
// (CI's time): the explicit step gave the same digits, and runs the 100 mm wave below.
TEST(FluidisedBedStability, AVerticalWaveOf50mmOnTwoCellSizes) {
    QS_SEMI_IMPLICIT_ONLY();
    expectWaveOnTwoCellSizes(0.0496, 0.03, 0.06);
}

// 16 and 32 cells a wavelength (2026-12-07, both schemes: growth -0.2 % and -1.5 %; speed
// -5.2 % and -1.3 %, order 1.94)
TEST(FluidisedBedStability, AVerticalWaveOf100mmOnTwoCellSizes) { expectWaveOnTwoCellSizes(0.0992, 0.03, 0.02); }

// ---------------------------------------------------------------------------------------------
// The particle phase (issue 42, item 2; physics/ParticlePhase.hpp): Foscolo and Gibilaro's
// elastic force, with the grid's front diffusion off (front_diffusion = 0), so that what holds
// the bed is the closure alone.

namespace {

/// The P0 sand with FG's force and no front diffusion; or 3 mm lead shot (rho_s = 11 340 kg/m3)
/// at n0 = 0.5, the literature's aggregative liquid-fluidised bed.
WaveBed closureBed(bool lead, double end) {
    WaveBed bed;
    bed.end = end;
    if (lead) {
        bed.n0 = 0.5;
        bed.thickness = 80 * 0.0062;   // 0.496 m: the waves rise at 0.22 m/s
        bed.outputInterval = 0.05;
    }
    bed.material = [lead](MaterialConfig& m) {
        if (lead) {
            m.grainDensity = 11340;
            m.permeability.grainSize = 3e-3;
        }
        m.particlePhase = ParticlePhaseModel::FoscoloGibilaro;
        m.particleGrainSize = m.permeability.grainSize;
        m.frontDiffusion = 0;
    };
    return bed;
}

}  // namespace

// Particulate: the P0 sand (u_e = 0.053 m/s against c = 6.3e-3 m/s). A 50 mm wave decays at
// k^2 (D_i - K/B), K/B = 6.3e-7 m2/s, whatever the cell: at 16 and 32 cells a wavelength the
// same -0.0096 1/s against the closed form's -0.0099 (2026-12-07: -2.7 % and -2.5 %). Without the particle phase the same run is
// neutral (-0.0001 1/s: the bare continuum's D_i k^2 = 1.6e-4 1/s), so the test fails with it off.
// Twelve seconds: the decay is slow (12 % of the amplitude), and a shorter fit is noisier.
// Semi-implicit only: on 1.55 mm cells the explicit step (the water's wave bounds it) needs
// 12 million steps; the force is the same code in both schemes (computeForces).
TEST(FluidisedBedStability, TheParticlePhaseDampsAWaveWhateverTheCell) {
    QS_SEMI_IMPLICIT_ONLY();
    const Outcome coarse = runWave(0.0496, 0.0031, closureBed(false, 12)), fine = runWave(0.0496, 0.00155, closureBed(false, 12));
    for (const Outcome& o : {coarse, fine}) {
        EXPECT_LT(o.expectedGrowth, 0);             // particulate: the closed form decays
        EXPECT_LT(std::abs(o.growthError), 0.10);
        EXPECT_LT(std::abs(o.growthError), 0.04);   // a guard near what is reached
    }
    // not the grid's: the two cells agree far closer than the front diffusion's h-proportional damping would
    EXPECT_NEAR(coarse.growth, fine.growth, 0.02 * std::abs(fine.expectedGrowth));
}

// Aggregative: 3 mm lead shot in water at n0 = 0.5 (u_e = 0.207 m/s against c = 0.227 m/s: FG
// call it aggregative; quicksand's 50 mm mode grows at 0.96 1/s). The bed's porosity rms, from
// the 1e-3 wave and the points' own discreteness, grows severalfold on 6.2 and 3.1 mm cells
// (2026-12-07, 0.75 s: see docs/verification.md, problem 12b) where the sand's falls: voidage
// waves form at both cells. Every wavelength grows, the shortest fastest, so the finer grid's rms
// grows more. And the closure slows it, as its sign says it must: without it the same beds grow
// faster (a closure of the wrong sign would too).
TEST(FluidisedBedStability, LeadShotFormsVoidageWavesOnBothCells) {
    for (double h : {0.0062, 0.0031}) {
        const Outcome with = runWave(0.0496, h, closureBed(true, 0.75));
        WaveBed bare = closureBed(true, 0.75);
        const auto closure = bare.material;
        bare.material = [closure](MaterialConfig& m) {
            closure(m);
            m.particlePhase = ParticlePhaseModel::None;
        };
        const Outcome without = runWave(0.0496, h, bare);
        EXPECT_GT(with.expectedGrowth, 0);               // aggregative: the closed form grows
        EXPECT_GT(with.rmsEnd, 3 * with.rmsStart) << "h = " << h;
        EXPECT_LT(with.rmsEnd, without.rmsEnd) << "h = " << h << ": the closure must slow the growth";
        std::printf("lead shot, h = %.4f m: rms x %.1f with the particle phase, x %.1f without\n", h,
                    with.rmsEnd / with.rmsStart, without.rmsEnd / without.rmsStart);
    }
}

// The front diffusion cut to the fronts (front_threshold = 0.01, as problem 7 runs it in
// test_BedExpansion.cpp): on a wave of amplitude 1e-3 it keeps (h k A / 0.01)^2 3/4 = 0.1 % of
// itself, and the particle phase decides the growth as without it (2026-12-07: -0.0097 1/s
// against -0.0100, +2.8 %, on 3.1 mm cells; in full, the front diffusion would damp the wave at
// -0.064 1/s, six times the closure).
TEST(FluidisedBedStability, TheFrontDiffusionAtFrontsOnlyLeavesTheWaveToTheParticlePhase) {
    QS_SEMI_IMPLICIT_ONLY();  // the same step as TheParticlePhaseDampsAWaveWhateverTheCell
    WaveBed bed = closureBed(false, 12);
    const auto closure = bed.material;
    bed.material = [closure](MaterialConfig& m) {
        closure(m);
        m.frontDiffusion = 0.25;
        m.frontThreshold = 0.01;
    };
    const Outcome o = runWave(0.0496, 0.0031, bed);
    EXPECT_LT(std::abs(o.growthError), 0.10);
    EXPECT_LT(std::abs(o.growthError), 0.04);  // a guard near what is reached
}

// ---------------------------------------------------------------------------------------------
// Lateral modes (physics.md section 7, "Lateral and oblique modes"): a porosity pattern across the
// bed n0 + A cos(k x), uniform up it.

namespace {

struct LateralFit {
    double growth = 0;  ///< 1/s, d ln a / dt of the cosine's amplitude a over the middle rows
    double r2 = 0;
    double firstAmplitude = 0, lastAmplitude = 0;
};

/// The cosine's amplitude a = sum n cos(k x) / sum cos^2(k x) over the sand cells of rows whose
/// centres lie in [z0, z1] (cos(k x) sums to zero over a row half a wavelength wide), at each
/// output, and ln a against t.
LateralFit fitLateralWave(const CaseRun& run, double k, double z0, double z1) {
    std::vector<double> t, lnA;
    for (std::size_t o = 0; o < run.cells.size(); ++o) {
        const SandCells& s = run.cells[o];
        double num = 0, den = 0;
        for (Index row = s.baseRow; row < s.rows(); ++row) {
            const double z = s.filterLevel + (static_cast<double>(row - s.baseRow) + 0.5) * s.h;
            if (z < z0 || z > z1) continue;
            for (Index col = 0; col < s.columns(); ++col) {
                const Index c = s.cell(col, row);
                if (s.state[c] == CellSand::None) continue;
                const double f = std::cos(k * (static_cast<double>(col) + 0.5) * s.h);
                num += f * s.porosity[c];
                den += f * f;
            }
        }
        t.push_back(run.series[o].time);
        lnA.push_back(std::log(std::abs(num / den)));
        if (std::getenv("QS_WAVE_TRACE")) std::printf("  t %.2f  a %.5e\n", t.back(), num / den);
    }
    LateralFit fit;
    fit.growth = slopeOf(t, lnA, &fit.r2);
    fit.firstAmplitude = std::exp(lnA.front());
    fit.lastAmplitude = std::exp(lnA.back());
    return fit;
}

struct LateralOutcome {
    double growth = 0, expected = 0, error = 0;
};

LateralOutcome runLateralWave(double wavelength, double cellSize, WaveBed spec) {
    spec.lateral = true;
    const CaseRun run = runWaveCase(wavelength, cellSize, spec);
    const CaseConfig& c = run.config;
    const auto& sand = c.material("sand");
    closed::FluidisedBed bed;
    bed.suspension = closed::SuspensionFlux::of(c, sand);
    bed.porosity = spec.n0;
    bed.maxPacking = 1 - sand.minPorosity;
    if (sand.particlePhase == ParticlePhaseModel::FoscoloGibilaro)
        bed.particleModulus =
            FoscoloGibilaro{sand.particleGrainSize, sand.grainDensity, c.liquid.density, c.gravity}.modulus(spec.n0);
    const double k = 2 * kPi / wavelength;
    const double expected = bed.growth(k, 0).real();
    const double H = c.sandTop() - c.filterLevel();
    const LateralFit fit = fitLateralWave(run, k, c.filterLevel() + 0.25 * H, c.filterLevel() + 0.75 * H);
    // relative to the closed form's rate; a neutral mode's (0) is judged by the caller
    LateralOutcome out{fit.growth, expected, expected != 0 ? (fit.growth - expected) / std::abs(expected) : 0.0};
    std::printf("lateral lambda %.4f m, h %.5f m: growth %.5f 1/s (closed form %.5f, %+.1f %%; ln a r^2 %.3f), a %.3e -> %.3e\n",
                wavelength, cellSize, fit.growth, expected, 100 * out.error, fit.r2, fit.firstAmplitude, fit.lastAmplitude);
    return out;
}

}  // namespace

// A lateral pattern, 16 cells a wavelength of 49.6 mm, in the middle half of the bed over its first
// 0.6 s. The closed form: neutral without the particle phase; with it, smoothed at
// K k^2 n0 phi0 / beta = (K/B) k^2 = 0.0101 1/s (the grains pushed down the porosity's lateral
// gradient against the slip's drag). Why so short a look: the denser columns, heavier by
// Delta rho g phi', sink as a whole (the water with the grains, physics.md) and turn at the filter
// and at the top, and once the columns have moved some 2 mm against each other (0.6 s) the
// points' crossing of cell faces scatters the cells' porosity by more than the closure's change.
// Until then the middle rows are clean (ln a against t: r^2 = 1.000). 2026-12-08: -0.00973 1/s
// (+4.0 %) with it, -0.00011 without; on 1.55 mm cells (2 min, not in the suite) -0.01001
// (+1.2 %). The shortfall falls as (kh)^2, as the closure's wide stencil says (sin(kh)/(kh))^2:
// 5 % and 1.3 %). Semi-implicit only (CI's time: the explicit step took 3 min for 1.25 s);
// the force is the same code in both (computeForces). QS_LATERAL_FINE=1 adds
// the 1.55 mm run.
TEST(FluidisedBedStability, TheParticlePhaseSmoothsALateralPatternAtItsClosedFormRate) {
    QS_SEMI_IMPLICIT_ONLY();
    WaveBed bed = closureBed(false, 0.6);
    bed.outputInterval = 0.05;
    const LateralOutcome with = runLateralWave(0.0496, 0.0031, bed);
    EXPECT_LT(with.expected, 0);
    EXPECT_LT(std::abs(with.error), 0.10);
    EXPECT_LT(std::abs(with.error), 0.055);  // a guard near what is reached
    const auto closure = bed.material;
    bed.material = [closure](MaterialConfig& m) {
        closure(m);
        m.particlePhase = ParticlePhaseModel::None;
    };
    const LateralOutcome without = runLateralWave(0.0496, 0.0031, bed);
    EXPECT_NEAR(without.expected, 0, 1e-12);
    // neutral: within 5 % of the closure's rate (reached 1.1 %)
    EXPECT_LT(std::abs(without.growth), 0.05 * std::abs(with.expected));
    if (std::getenv("QS_LATERAL_FINE")) {  // the 1.55 mm figure above
        bed.material = closure;
        runLateralWave(0.0496, 0.00155, bed);
    }
}
