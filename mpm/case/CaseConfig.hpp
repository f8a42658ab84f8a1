#pragma once
// CaseConfig: the validated content of a case directory's case.toml, as a plain struct.
//
// Only case/CaseLoader (with its toolkit, case/TomlSection) reads TOML; everything else sees this
// struct (the solver never reads a key by name). Every field is SI; the key it comes from, its
// unit, default and allowed range are documented in docs/case-format.md, which follows the order
// of this file.
//
// Geometry of a column (vertical axis z, elevations measured from the gate plane z = 0):
//
//   z_top      -- top of the background grid
//   overflow   -- water passing it spills over a weir (boundary/Overflow.hpp) and counts as outflow
//   water      -- initial free surface of the liquid
//   sand top   -- filter + sum of layer thicknesses
//   filter     -- the permeable gate: solid held, liquid passes (= chamber height)
//   0          -- chamber bottom: the gate pressure acts here on the liquid
#include <cmath>
#include <optional>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "case/CaseOverride.hpp"
#include "core/ModelChoices.hpp"

namespace qs {

struct GridConfig {
    int dimension = 1;                 ///< 1, 2 or 3 (only 1 is verified)
    double cellSize = 0.0;             ///< m, edge of the square/cubic cells
    double width = 0.0;                ///< m, horizontal extent in 2D/3D (ignored in 1D); the
                                       ///<    radius in axisymmetry
    double crossSectionArea = 0.0;     ///< m2, column cross-section (1D: the area of every cell;
                                       ///<     2D plane: area/width is the out-of-plane thickness;
                                       ///<     3D: width^2; axisymmetric: pi width^2)
    GridGeometry geometry = GridGeometry::Plane;
    ShapeFunctionKind shapeFunctions = ShapeFunctionKind::Linear;
};

struct ColumnConfig {
    double chamberHeight = 0.0;        ///< m, free-water chamber below the filter (>= 1 cell)
    double waterLevel = 0.0;           ///< m, initial free surface elevation (>= sand top)
    std::optional<double> overflowLevel;  ///< m, outflow level (>= waterLevel); none: no outflow
    SandOverflow sandOverflow = SandOverflow::Carry;  ///< sand reaching the overflow level
    double top = 0.0;                  ///< m, top of the grid (> overflow and water levels)
    /// degrees, delta: the sand's friction angle on the lateral walls (Coulomb, tau <= tan(delta)
    /// sigma'_n; boundary/RoughWalls.hpp); 0 is a smooth wall. 2D and 3D only; in axisymmetry the
    /// outer wall (the axis stays a line of symmetry)
    double wallFrictionAngle = 0.0;
};

struct PermeabilityConfig {
    PermeabilityMode mode = PermeabilityMode::Constant;
    double value = 0.0;                ///< m2, kappa (Constant) or kappa0 at n0 (KozenyCarmanScaled)
    double grainSize = 0.0;            ///< m, D in kappa = D^2 n^3 / (A (1-n)^2) (KozenyCarman)
};

struct MaterialConfig {
    std::string name;                  ///< the key under [materials]
    ConstitutiveModelKind model = ConstitutiveModelKind::LinearElastic;
    double grainDensity = 2650.0;      ///< kg/m3, rho_s
    double porosity = 0.38;            ///< -, n0 in (0,1)
    double maxPorosity = 0.41;         ///< -, n_max in (n0, 1): liquid-state switch
    double minPorosity = 0.32;         ///< -, n_min in (0, n0]: the densest packing; sizes injected liquid points
    double youngsModulus = 1e6;        ///< Pa
    double poissonRatio = 0.3;         ///< -, in [0, 0.5)
    double frictionAngle = 30.0;       ///< degrees (MohrCoulomb)
    double dilatancyAngle = 0.0;       ///< degrees (MohrCoulomb), in [0, friction angle]
    double cohesion = 0.0;             ///< Pa (MohrCoulomb)
    double tensileStrength = 0.0;      ///< Pa (MohrCoulomb), tension cut-off in [0, c cot phi]
    double k0 = 0.5;                   ///< -, lateral earth-pressure coefficient at rest
    PermeabilityConfig permeability;
    bool ergun = true;                 ///< Forchheimer (Ergun) term on
    double ergunA = 150.0;             ///< -, Ergun/Kozeny-Carman A
    double ergunB = 1.75;              ///< -, Ergun B
    /// the fluidised sand's particle phase: none (the grains carry no stress once fluidised), or
    /// Foscolo and Gibilaro's elastic force (physics/ParticlePhase.hpp)
    ParticlePhaseModel particlePhase = ParticlePhaseModel::None;
    double particleGrainSize = 0.0;    ///< m, d of Foscolo and Gibilaro's modulus
    double frontDiffusion = 0.25;      ///< -, alpha of the kinematic front diffusion D = alpha h c (0: none)
    /// -, s: the front diffusion fades where the porosity changes by less than s over a cell,
    /// D (h |grad phi| / s)^2 below it (0: everywhere in full, as before)
    double frontThreshold = 0.0;
    /// close packing held: a contact pressure on the grains where the grid's sand porosity falls
    /// below min_porosity (physics/ClosePacking.hpp); off by default
    bool closePacking = false;
};

/// A horizontal range [from, to] (m) on one horizontal axis; the whole width when absent.
struct HorizontalRange {
    double from = 0.0, to = 0.0;
    bool contains(double x) const { return x >= from && x < to; }
};

/// A part of a layer, side by side with the rest of it, made of another material: the layer's
/// points whose horizontal position lies within x (and y in 3D) take it (2D and 3D only).
struct ZoneConfig {
    std::string material;              ///< a key of [materials]
    HorizontalRange x;                 ///< m
    std::optional<HorizontalRange> y;  ///< m (3D); the whole width when absent
    bool contains(const double* position, int dimension) const {
        return x.contains(position[0]) && (dimension < 3 || !y || y->contains(position[1]));
    }
};

struct LayerConfig {
    std::string material;              ///< a key of [materials]
    double thickness = 0.0;            ///< m
    std::vector<ZoneConfig> zones;     ///< [[layers.zones]]: other materials side by side
    /// The material at a horizontal position (the last zone that holds it, else the layer's).
    const std::string& materialAt(const double* position, int dimension) const {
        for (std::size_t k = zones.size(); k-- > 0;)
            if (zones[k].contains(position, dimension)) return zones[k].material;
        return material;
    }
};

struct LiquidConfig {
    /// Pa: the paper's deliberately soft water (a hundredth of real water's), the explicit
    /// scheme's default, whose step it lets be ten times longer
    static constexpr double kSoftBulkModulus = 2.128e7;
    /// Pa: water as it is, the semi-implicit scheme's default (its step does not see K_L)
    static constexpr double kRealBulkModulus = 2.2e9;
    double density = 998.2;            ///< kg/m3, rho_L
    double bulkModulus = kSoftBulkModulus;  ///< Pa, K_L; when not given, by time.scheme
    /// false: K_L is the default of the scheme the case was loaded with (CaseLoader), which code
    /// that switches time.scheme afterwards (the verification suite) leaves as it was
    bool bulkModulusGiven = true;
    /// Which default water K_L is, for the messages: "real water, the semi-implicit scheme's
    /// default" or "the paper's soft water, the explicit scheme's default"
    const char* defaultWaterName() const {
        return bulkModulus == kRealBulkModulus ? "real water, the semi-implicit scheme's default"
                                               : "the paper's soft water, the explicit scheme's default";
    }
    double viscosity = 8.91e-4;        ///< Pa s, mu
    double cavitationPressure = 0.0;   ///< Pa (gauge), lowest pore pressure the liquid takes
    bool freeSurfaceZeroPressure = false;  ///< set p = 0 on free-surface liquid points
    double freeSurfaceFilling = 0.9;   ///< -, filling ratio below which a top cell is free surface
    bool gridLiquidMass = true;        ///< nodal liquid mass rho_L n_i V_i below the free surface
    double picShare = 0.0;             ///< -, share of the grid's velocity (PIC) in the liquid points' each step
    /// s, the blend's damping time T instead of a share per step: alpha = 1 - exp(-dt / T), the
    /// same damping per second whatever the step (0: pic_share holds)
    double picDampingTime = 0.0;
    /// -, the blend's share in a step of dt
    double picShareFor(double dt) const { return picDampingTime > 0 ? -std::expm1(-dt / picDampingTime) : picShare; }
};

struct PointsConfig {
    int solidPerCell = 2;              ///< solid points per cell and direction
    int liquidPerCell = 2;             ///< liquid points per sand cell and direction
};

/// [initial.porosity_field]: n(x) = n0 + standard_deviation g(x), g a Gaussian random field of
/// unit variance (physics/RandomPorosityField.hpp), clipped to [n_min, n_max).
struct PorosityFieldConfig {
    bool enabled = false;
    double standardDeviation = 0.0;  ///< -, of the porosity
    double correlationLength = 0.0;  ///< m
    std::uint64_t seed = 0;
    bool mirror = false;             ///< the field reflected across x = width/2 (2D plane, 3D)
};

/// A sinusoidal porosity perturbation, n0 + amplitude sin(2 pi s / wavelength), s the height above
/// the filter (vertical), or n0 + amplitude cos(2 pi x / wavelength) (lateral: symmetric about the
/// walls): the linear stability problem (physics.md section 7)
struct PorosityWaveConfig {
    bool enabled = false;
    double amplitude = 0.0;          ///< -, of the porosity
    double wavelength = 0.0;         ///< m
    bool lateral = false;            ///< along x (2D, 3D) instead of up the column
};

struct InitialConfig {
    InitialState state = InitialState::Solid;  ///< Fluidised: a suspension, n0 >= n_max allowed
    InitialStress stress = InitialStress::K0;
    bool rigidSkeleton = false;        ///< solid held everywhere (seepage through a fixed bed)
    double filterVelocity = 0.0;       ///< m/s, initial steady upward seepage q0 (pressure and
                                       ///<    effective stress to match, liquid moving)
    bool undrainedSurcharge = false;   ///< start from the undrained state under the surcharge
    double gravityStageDuration = 0.0; ///< s, quasi-static stage before t = 0 (0: none)
    double gravityStageDamping = 0.05; ///< -, local damping alpha in that stage
    /// s, the grains' buoyant weight rises linearly from zero over this time at the stage's start
    /// (a quasi-static loading, as a silo fills; 0: the whole weight at once). The water weighs its
    /// whole weight throughout, so the pore water stays hydrostatic.
    double gravityStageRamp = 0.0;
    PorosityFieldConfig porosityField; ///< a random porosity field over the sand (off by default)
    PorosityWaveConfig porosityWave;   ///< a sinusoidal porosity perturbation (off by default)
};

struct LoadConfig {
    double surcharge = 0.0;            ///< Pa, compressive load on the sand top (solid phase)
    double surchargeRampTime = 0.0;    ///< s, linear ramp of the surcharge from t = 0
};

struct GateConfig {
    GateMode mode = GateMode::Pressure;
    double flux = 0.0;                 ///< m/s, liquid velocity at the gate (Flux mode)
    double fluxRampTime = 0.0;         ///< s, linear ramp of that velocity from t = 0
};

struct ReservoirConfig {
    ReservoirKind kind = ReservoirKind::ConstantHead;
    double head = 0.0;                 ///< m, elevation of the reservoir surface above the gate
                                       ///<    plane (the initial level for Lumped and OpenFoam)
    double headRate = 0.0;             ///< m/s, linear change of the head (ConstantHead)
    double area = 0.0;                 ///< m2, reservoir plan area (Lumped, OpenFoam)
    /// (level m, plan area m2) rows: the plan area by level, replacing `area` (Lumped, OpenFoam)
    std::vector<std::pair<double, double>> areaTable;
    /// (time s, head m) rows: the head by time, linear between rows (ConstantHead); `head` is
    /// then the first row's
    std::vector<std::pair<double, double>> headSchedule;
    double tubeDiameter = 0.0;         ///< m, U-tube inner diameter (Lumped; 0: no tube)
    double tubeLength = 0.0;           ///< m, U-tube length (Lumped)
    double minorLoss = 0.0;            ///< -, sum of minor-loss coefficients (Lumped)
    TubeFriction tubeFriction = TubeFriction::SmoothPipe;  ///< wall friction of the tube (Lumped)
    std::string openfoamCase;          ///< path of the OpenFOAM case directory (OpenFoam)
    std::string gatePatch = "gate";    ///< OpenFOAM patch coupled to the gate
    std::string reservoirPatch = "reservoir";  ///< OpenFOAM patch carrying the reservoir level
};

/// How the MPM and a windowed reservoir model (OpenFOAM) exchange flux and pressure.
struct CouplingConfig {
    CouplingKind scheme = CouplingKind::Implicit;
    double window = 1e-3;              ///< s, coupling window = the CFD time step (>= MPM dt)
    double tolerance = 1e-3;           ///< -, implicit: |flux residual| / |flux| to accept a window
    int maxIterations = 30;            ///< implicit: iterations per window before giving up
    double relaxation = 0.5;           ///< -, implicit: first Aitken relaxation factor, (0, 1]
};

struct TimeConfig {
    double end = 1.0;                  ///< s, simulated time
    TimeScheme scheme = TimeScheme::Explicit;
    PressureSolver pressureSolver = PressureSolver::Automatic;  ///< semi-implicit scheme only
    double courant = 0.4;              ///< -, dt = courant * h / c, c the scheme's wave speed, in (0, 0.5]
    std::optional<double> dt;          ///< s, fixed step (must not exceed the stable one)
    double outputInterval = 0.01;      ///< s
    double checkpointInterval = 0.0;   ///< s of simulated time (0: only at the end)
};

struct MonitorConfig {
    std::string name;
    double elevation = 0.0;            ///< m, section where the filter velocity is measured
    std::optional<HorizontalRange> x;  ///< m, part of the section (2D, 3D); whole width if absent
    std::optional<HorizontalRange> y;  ///< m, (3D)
};

struct OutputConfig {
    std::string directory = "output";  ///< relative to the case directory
    bool fields = true;                ///< write fields.h5 + fields.xdmf
    double progressInterval = 2.0;     ///< s of wall time between progress lines
};

struct CaseConfig {
    std::string caseDirectory;         ///< where case.toml was read from
    std::string title;
    GridConfig grid;
    ColumnConfig column;
    std::vector<MaterialConfig> materials;
    std::vector<LayerConfig> layers;   ///< bottom to top, starting at the filter
    LiquidConfig liquid;
    PointsConfig points;
    double gravity = 9.81;             ///< m/s2
    InitialConfig initial;
    LoadConfig loads;
    GateConfig gate;
    ReservoirConfig reservoir;
    CouplingConfig coupling;
    TimeConfig time;
    std::vector<MonitorConfig> monitors;
    OutputConfig output;
    /// the command line's overrides (--set KEY=VALUE), in order, and the case as run (TOML),
    /// written to OUTPUT/case.effective.toml
    std::vector<CaseOverride> overrides;
    std::string effectiveCase;

    const MaterialConfig& material(const std::string& name) const;
    double sandTop() const;            ///< m, filter + sum of layer thicknesses
    double filterLevel() const { return column.chamberHeight; }
};

}  // namespace qs
