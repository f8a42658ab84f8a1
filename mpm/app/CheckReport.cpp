#include "app/CheckReport.hpp"

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

#include "core/Constants.hpp"
#include "coupling/WindowedModel.hpp"
#include "physics/ClosePacking.hpp"
#include "physics/ClosedForms.hpp"
#include "physics/PipeFriction.hpp"
#include "physics/WaveSpeeds.hpp"
#include "physics/DragLaw.hpp"
#include "physics/FluidisedBedStability.hpp"
#include "physics/FrontDiffusion.hpp"
#include "physics/ParticlePhase.hpp"
#include "physics/Permeability.hpp"
#include "solver/ColumnBuilder.hpp"
#include "solver/RunPreconditions.hpp"
#include "solver/RunSize.hpp"
#include "solver/TimeLattice.hpp"

namespace qs {

namespace {
// Once fluidised (at n_max, where it starts): Kynch's kinematic wave speed c against Foscolo and
// Gibilaro's elastic one u_e, their verdict, and what holds the bed uniform in quicksand: the
// particle phase's diffusion K / B and the grid's front diffusion (physics.md section 7)
void printFluidised(std::ostream& out, const CaseConfig& config, const MaterialConfig& m) {
    if (!(config.gravity > 0)) return;
    const double n = std::min(m.maxPorosity, 0.9);
    closed::FluidisedBed bed;
    bed.suspension = closed::SuspensionFlux::of(config, m);
    bed.porosity = n;
    bed.maxPacking = 1 - m.minPorosity;
    const double d = m.particleGrainSize > 0 ? m.particleGrainSize : m.permeability.grainSize;
    const FoscoloGibilaro fg{d, m.grainDensity, config.liquid.density, config.gravity};
    const auto base = bed.base();
    const double D = frontDiffusivity(DragLaw{config.liquid.viscosity, config.liquid.density}, PermeabilityLaw::from(m),
                                      m.grainDensity, config.gravity, m.maxPorosity, config.grid.cellSize, m.frontDiffusion);
    out << "  fluidised at n_max: kinematic wave c      " << base.kinematicSpeed << " m/s";
    if (d > 0)
        out << ", Foscolo-Gibilaro u_e " << fg.elasticWaveSpeed(n) << " m/s: "
            << (fg.elasticWaveSpeed(n) > base.kinematicSpeed ? "particulate" : "aggregative") << " by their criterion";
    out << "\n";
    if (m.particlePhase == ParticlePhaseModel::FoscoloGibilaro) {
        // quicksand's own criterion, the water's inertia included (physics.md section 7)
        const double c = base.kinematicSpeed, V0 = base.waterVelocity;
        const double inertia = m.grainDensity * n * c * c + config.liquid.density * (1 - n) * (V0 - c) * (V0 - c);
        out << "  quicksand's own criterion                rho_s n c^2 + rho_L phi (V0 - c)^2 = " << inertia
            << " Pa against K = " << fg.modulus(n) << " Pa: " << (inertia < fg.modulus(n) ? "stable" : "unstable")
            << "\n";
    }
    out << "  what holds it uniform                    ";
    if (m.particlePhase == ParticlePhaseModel::FoscoloGibilaro)
        out << "particle phase K / B = " << fg.modulus(n) / base.dragCoefficient << " m2/s (K = " << fg.modulus(n)
            << " Pa), ";
    else
        out << "no particle phase (materials." << m.name << ".particle_phase = \"none\"), ";
    out << "front diffusion " << D << " m2/s (alpha " << m.frontDiffusion << " on " << config.grid.cellSize << " m cells";
    if (m.frontThreshold > 0) out << ", fading below a porosity change of " << m.frontThreshold << " over a cell";
    out << ")\n";
    if (m.particlePhase == ParticlePhaseModel::None && (m.frontDiffusion == 0 || m.frontThreshold > 0))
        out << "  note: with the front diffusion cut and no particle phase, nothing holds a small porosity perturbation "
               "of the fluidised sand: its equations are unstable at every wavelength (physics.md section 7)\n";
}
}  // namespace

namespace {
/// A step count to print: a whole number while it fits, else the double (an absurd case,
/// e.g. a bulk modulus typed in the wrong unit, must not print an overflowed integer).
std::string stepCount(double steps) {
    std::ostringstream s;
    if (steps < 1e15) s << std::llround(steps);
    else s << steps;
    return s.str();
}
}  // namespace

double expectedSteadyFilterVelocity(const CaseConfig& config) {
    if (config.gate.mode != GateMode::Pressure) return 0.0;
    if (config.reservoir.kind == ReservoirKind::OpenFoam) return 0.0;
    const double g = config.gravity, rho = config.liquid.density, mu = config.liquid.viscosity;
    const double tail = config.column.overflowLevel ? *config.column.overflowLevel : config.column.waterLevel;
    const double dh = config.reservoir.head - tail;
    const auto& r = config.reservoir;
    const bool hasTube = r.kind == ReservoirKind::Lumped && r.tubeDiameter > 0;
    // the tube's head loss at filter velocity q: wall friction (Hagen-Poiseuille times the
    // turbulent multiplier f Re / 64, as the lumped reservoir) and the minor losses K U^2 / 2g
    auto tubeLoss = [&](double q) {
        if (!hasTube) return 0.0;
        const double Q = q * config.grid.crossSectionArea, At = kPi * r.tubeDiameter * r.tubeDiameter / 4;
        const double re = rho * std::abs(Q / At) * r.tubeDiameter / mu;
        const double phi = r.tubeFriction == TubeFriction::SmoothPipe ? friction::frictionMultiplier(re) : 1.0;
        return closed::tubeResistance(r.tubeDiameter, r.tubeLength, rho, g, mu) * phi * Q +
               r.minorLoss * (Q / At) * std::abs(Q / At) / (2 * g);
    };
    // head lost at filter velocity q: sum over layers of L (mu q/kappa + F rho q|q|/sqrt(kappa)) / (rho g)
    auto loss = [&](double q) {
        double h = tubeLoss(q);
        for (const auto& layer : config.layers) {
            const auto& m = config.material(layer.material);
            const auto law = PermeabilityLaw::from(m);
            h += layer.thickness * DragLaw{mu, rho}.gradient(law.kappa(m.porosity), law.ergunFactor(m.porosity), q) / (rho * g);
        }
        return h;
    };
    if (dh == 0) return 0.0;
    double qlo = -1.0, qhi = 1.0;  // m/s, far beyond any seepage velocity
    for (int k = 0; k < 200; ++k) {  // bisection: loss(q) increases monotonically
        const double q = 0.5 * (qlo + qhi);
        (loss(q) < dh ? qlo : qhi) = q;
    }
    return 0.5 * (qlo + qhi);
}

void printRunSize(const CaseConfig& config, std::ostream& out) {
    const RunSize r = estimateRunSize(config);
    const MachineMemory machine = machineMemory();
    out << "size: " << r.cells << " cells, " << r.nodes << " nodes, " << r.solidPoints << " solid + "
        << r.liquidPoints << " liquid points (room for " << r.liquidCapacity << " liquid), "
        << r.steps << " steps\n";
    out << "estimated peak memory " << formatBytes(r.peakBytes) << " of the machine's "
        << formatBytes(machine.total);
    if (machine.available > 0) out << " (" << formatBytes(machine.available) << " available now)";
    out << "\n";
    out << "estimated wall time " << formatSeconds(r.wallSeconds) << " on one thread (at "
        << kThroughput[config.grid.dimension - 1] << " point updates/s in " << config.grid.dimension
        << "D, docs/performance.md"
        << (config.reservoir.kind == ReservoirKind::OpenFoam ? "; doubled for the OpenFOAM tube" : "")
        << ")\n";
    if (machine.available > 0 && r.peakBytes > machine.available && r.peakBytes <= machine.total)
        out << "note: the run needs more memory than is available now; other programs may have to give way\n";
    if (r.wallSeconds > 86400)
        out << "note: over a day of wall time; grid.cell_size (now " << config.grid.cellSize
            << " m) sets both the step count and the point count\n";
}

void printCheckReport(const CaseConfig& config, std::ostream& out) {
    validateRun(config);  // what run refuses before its first step, check refuses too, saying the same
    const double g = config.gravity, rho = config.liquid.density, mu = config.liquid.viscosity;
    const double KL = config.liquid.bulkModulus, h = config.grid.cellSize;
    out << std::setprecision(4);
    out << "case " << config.caseDirectory << (config.title.empty() ? "" : ": " + config.title) << "\n";
    for (const CaseOverride& o : config.overrides) out << "  with " << o.text() << "\n";
    out << "geometry: " << config.grid.dimension << "D";
    if (config.grid.geometry == GridGeometry::Axisymmetric)
        out << " axisymmetric (r, z), radius " << config.grid.width << " m";
    else if (config.grid.dimension == 2)
        out << " plane strain, width " << config.grid.width << " m";
    else if (config.grid.dimension == 3)
        out << ", " << config.grid.width << " m x " << config.grid.width << " m";
    out << ", cross-section " << config.grid.crossSectionArea << " m2, cell " << h << " m, gate z = 0, filter "
        << config.filterLevel() << " m, sand top " << config.sandTop() << " m, water "
        << config.column.waterLevel << " m";
    if (config.column.overflowLevel) out << ", overflow " << *config.column.overflowLevel << " m";
    out << ", grid top " << config.column.top << " m\n";
    if (config.grid.dimension > 1) {
        const double delta = config.column.wallFrictionAngle;
        if (delta > 0)
            out << "walls: rough, sand on wall friction angle " << delta << " deg (mu = " << std::tan(delta * kPi / 180)
                << ")" << (config.grid.geometry == GridGeometry::Axisymmetric ? ", the outer wall" : "") << "\n";
        else
            out << "walls: smooth (column.wall_friction_angle = 0)\n";
    }
    if (config.initial.gravityStageRamp > 0)
        out << "gravity stage: " << config.initial.gravityStageDuration << " s, the grains' buoyant weight ramped over "
            << config.initial.gravityStageRamp << " s, local damping " << config.initial.gravityStageDamping << "\n";
    if (const auto& w = config.initial.porosityWave; w.enabled)
        out << "porosity wave: n0 + " << w.amplitude << (w.lateral ? " cos(2 pi x / " : " sin(2 pi (z - filter) / ")
            << w.wavelength << " m)" << (w.lateral ? ", across the column" : ", up the column") << "\n";
    if (const auto& f = config.initial.porosityField; f.enabled)
        out << "random porosity field: n0 + " << f.standardDeviation << " g(x), correlation length "
            << f.correlationLength << " m, seed " << f.seed << " (clipped to [n_min, n_max - 0.001])\n";

    for (const auto& m : config.materials) {
        const auto law = PermeabilityLaw::from(m);
        const double n = m.porosity, kappa = law.kappa(n);
        const double Eoed = closed::oedometricModulus(m.youngsModulus, m.poissonRatio);
        const auto waves = closed::zeroDragWaveSpeeds(Eoed, KL, n, m.grainDensity, rho);
        // K = kappa rho g / mu needs gravity; without it, quote K at standard gravity
        const bool weightless = !(g > 0);
        const double K = closed::hydraulicConductivity(kappa, rho, weightless ? 9.81 : g, mu);
        out << "material '" << m.name << "' (n0 = " << n << ", n_max = " << m.maxPorosity << ")\n";
        out << "  critical gradient i_c = (Gs-1)(1-n0)     " << closed::criticalGradient(m.grainDensity, rho, n) << "\n";
        out << "  permeability kappa(n0)                   " << kappa << " m2\n";
        out << "  hydraulic conductivity K                 " << K << " m/s"
            << (weightless ? " (at g = 9.81 m/s2: this case has gravity = 0, where K is not defined; kappa and "
                             "mu set the flow)"
                           : "")
            << "\n";
        if (m.permeability.grainSize > 0)
            out << "  Kozeny-Carman kappa from grain size      "
                << closed::kozenyCarman(m.permeability.grainSize, n, m.ergunA) << " m2\n";
        out << "  Ergun factor F(n0)                       " << law.ergunFactor(n)
            << (m.ergun ? "" : " (Forchheimer term off)") << "\n";
        out << "  oedometric modulus E_oed                 " << Eoed << " Pa\n";
        out << "  wave speeds fast / slow / undrained      " << waves.fast << " / " << waves.slow << " / "
            << closed::undrainedWaveSpeed(Eoed, KL, n, m.grainDensity, rho) << " m/s\n";
        out << "  skeleton's own wave sqrt(E_oed/((1-n)rho_s)) "
            << mixtureWaves(Eoed, KL, n, m.grainDensity, rho).skeleton << " m/s\n";
        // c_v = k/(gamma_w (m_v + n/K_L)) = (kappa/mu)/(m_v + n/K_L): independent of g
        out << "  consolidation coefficient c_v            "
            << (kappa / mu) / (1 / Eoed + n / KL) << " m2/s\n";
        printFluidised(out, config, m);
        if (m.closePacking) {
            const double M = ClosePacking::modulusForStep(schemeWaveSpeed(config), m.grainDensity, m.minPorosity);
            out << "  close packing held below n_min           M = " << M << " Pa (a packing wave at half the step's "
                << schemeWaveSpeed(config) << " m/s): a kPa holds a cell " << 1e3 * (1 - m.minPorosity) / M
                << " under n_min\n";
        }
    }
    // the step the solver takes (solver/RunSize.hpp): the same c_fast as the closed forms above,
    // from the materials' constitutive models
    const bool semi = config.time.scheme == TimeScheme::SemiImplicit;
    const double cFast = fastestWaveSpeed(config), cSkeleton = skeletonWaveSpeed(config);
    const TimeLattice lattice = timeLattice(config);
    out << "time step (" << (semi ? "semi-implicit" : "explicit") << " scheme): c_fast = " << cFast
        << " m/s, c_skeleton = " << cSkeleton << " m/s; "
        << (config.time.dt ? "time.dt" : std::string("courant h / ") + (semi ? "c_skeleton" : "c_fast")) << " = "
        << lattice.stableDt << " s, fitted to dt = " << lattice.dt << " s: " << lattice.stepsPerOutput
        << " steps fill each output interval of " << config.time.outputInterval << " s ("
        << stepCount(config.time.end / lattice.dt) << " steps to t = " << config.time.end << " s)\n";
    out << "  water: K_L = " << config.liquid.bulkModulus << " Pa"
        << (config.liquid.bulkModulusGiven ? "" : std::string(" (not given: ") + config.liquid.defaultWaterName() + ")")
        << "\n";
    if (!semi && cFast > 2 * cSkeleton) {
        out << "  time.scheme = \"semi_implicit\" would step " << cFast / cSkeleton
            << " times further (its step follows the skeleton's wave, not the water's)";
        if (!config.liquid.bulkModulusGiven)
            out << "; without liquid.bulk_modulus it takes real water, " << LiquidConfig::kRealBulkModulus
                << " Pa: give bulk_modulus = " << config.liquid.bulkModulus << " to keep this water";
        out << "\n";
    }
    printRunSize(config, out);
    out << "points: " << config.points.solidPerCell << " solid and " << config.points.liquidPerCell
        << " liquid per sand cell and axis, " << freeWaterPointsPerCell(config)
        << " liquid per free-water cell vertically\n";
    if (config.gate.mode == GateMode::Pressure && config.reservoir.kind != ReservoirKind::OpenFoam) {
        const double tail = config.column.overflowLevel ? *config.column.overflowLevel : config.column.waterLevel;
        double L = 0;
        for (const auto& l : config.layers) L += l.thickness;
        const double i = (config.reservoir.head - tail) / L;
        const double q = expectedSteadyFilterVelocity(config);
        out << "reservoir head " << config.reservoir.head << " m over tailwater " << tail
            << " m: overall gradient " << i << "\n";
        out << "expected steady filter velocity (Darcy-Forchheimer";
        if (config.reservoir.kind == ReservoirKind::Lumped && config.reservoir.tubeDiameter > 0) out << " + tube";
        out << ") " << q << " m/s, flux " << q * config.grid.crossSectionArea << " m3/s\n";
        const auto& r = config.reservoir;
        if (r.kind == ReservoirKind::Lumped && r.tubeDiameter > 0) {
            const double U = q * config.grid.crossSectionArea / (kPi * r.tubeDiameter * r.tubeDiameter / 4);
            const double re = rho * std::abs(U) * r.tubeDiameter / config.liquid.viscosity;
            out << "tube: mean velocity " << U << " m/s, Re " << re << " ("
                << (re < 2000 ? "laminar" : re < 4000 ? "transitional" : "turbulent") << "), friction factor "
                << (r.tubeFriction == TubeFriction::SmoothPipe ? friction::churchill(std::max(re, 1e-12))
                                                               : 64 / std::max(re, 1e-12))
                << (r.tubeFriction == TubeFriction::SmoothPipe ? " (smooth pipe)" : " (laminar, 64/Re)")
                << ", minor losses K = " << r.minorLoss << "\n";
            if (re > 2000 && r.tubeFriction == TubeFriction::Laminar)
                out << "note: the tube's Re is above 2000 but reservoir.tube_friction = \"laminar\": its loss is "
                       "underestimated; tube_friction = \"smooth_pipe\" gives the turbulent friction\n";
        }
        const auto& m0 = config.material(config.layers.front().material);
        if (i > closed::criticalGradient(m0.grainDensity, rho, m0.porosity) && !config.initial.rigidSkeleton)
            out << "note: the gradient exceeds the critical gradient: the bed will heave and fluidise\n";
    }
    if (config.reservoir.kind == ReservoirKind::OpenFoam) {
        out << "reservoir: OpenFOAM case " << config.reservoir.openfoamCase << " (patches '"
            << config.reservoir.gatePatch << "', '" << config.reservoir.reservoirPatch << "'), level "
            << config.reservoir.head << " m, area " << config.reservoir.area << " m2\n";
        out << "coupling: " << (config.coupling.scheme == CouplingKind::Implicit ? "implicit (Aitken)" : "explicit")
            << ", window " << lattice.window << " s = " << lattice.stepsPerWindow << " MPM steps";
        if (lattice.window != config.coupling.window)
            out << " (coupling.window " << config.coupling.window << " s, fitted into the output interval)";
        out << "\n";
        for (const auto& line : checkOpenFoamCase(config)) out << "  " << line << "\n";
        CaseConfig withoutTube = config;  // the column alone: an upper bound of the flux
        withoutTube.reservoir.kind = ReservoirKind::ConstantHead;
        const double q = expectedSteadyFilterVelocity(withoutTube);
        out << "expected steady filter velocity without the tube's loss " << q << " m/s (the tube lowers it)\n";
    }
    out << "case OK\n";
}

}  // namespace qs
