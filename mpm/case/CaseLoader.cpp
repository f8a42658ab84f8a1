// The case format: the tables and keys of case.toml, and how each is read into CaseConfig. This
// file is the schema, docs/case-format.md in code: it reads each key on its own (its type, its
// range, whether it applies with the choices made elsewhere) with the toolkit of case/TomlSection.
// The rules that relate the values of several keys are case/CaseRules, checked on the CaseConfig.
#include "case/CaseLoader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include "core/Constants.hpp"
#include "core/Error.hpp"
#include "core/PiecewiseLinear.hpp"
#include "case/CaseOverrides.hpp"
#include "case/CaseRules.hpp"
#include "case/DidYouMean.hpp"
#include "case/KeyLocations.hpp"
#include "case/MessageText.hpp"
#include "case/Range.hpp"
#include "case/TomlSection.hpp"

namespace qs {
namespace {

// ------------------------------------------------------------------------------------------------
// The keys each table accepts. This is the one list the unknown-key check reads; the order is the
// order of docs/case-format.md. A reader asking for a key not listed here trips a debug assert.
// ------------------------------------------------------------------------------------------------

constexpr const char* kRootKeys[] = {"title",  "grid",      "column",  "materials", "layers",
                                     "liquid", "points",    "gravity", "initial",   "loads",
                                     "gate",   "reservoir", "coupling", "time",   "monitors",
                                     "output"};
constexpr const char* kGridKeys[] = {"dimension", "cell_size", "width", "cross_section_area",
                                     "shape_functions", "geometry"};
constexpr const char* kColumnKeys[] = {"chamber_height", "water_level", "overflow_level", "sand_overflow", "top", "wall_friction_angle"};
constexpr const char* kMaterialKeys[] = {
    "model",          "grain_density", "porosity",       "max_porosity",    "min_porosity",
    "youngs_modulus", "poisson_ratio", "friction_angle", "dilatancy_angle", "cohesion",
    "tensile_strength", "k0",          "ergun",          "ergun_a",         "ergun_b",
    "permeability",   "particle_phase", "particle_grain_size", "front_diffusion", "front_threshold",
    "close_packing"};
constexpr const char* kPermeabilityKeys[] = {"mode", "value", "grain_size"};
/// kg/m3: below this a grain density is taken for a unit mistake (g/cm3); the lightest
/// granular media modelled this way (plastic beads) are about 1 000 kg/m3.
constexpr double kMinGrainDensity = 500.0;
// The densest packings of real sands and gravels stay above about 0.2 (equal spheres: 0.26); the
// free water's lattice has ceil(liquid_per_cell / n_min) points per cell height, so an n_min near
// zero asks for an unbounded number of points.
constexpr double kMinMinPorosity = 0.05;
constexpr const char* kLayerKeys[] = {"material", "thickness", "zones"};
constexpr const char* kZoneKeys[] = {"material", "x", "y"};
constexpr const char* kLiquidKeys[] = {"density",
                                       "bulk_modulus",
                                       "viscosity",
                                       "cavitation_pressure",
                                       "free_surface_zero_pressure",
                                       "free_surface_filling",
                                       "grid_liquid_mass",
                                       "pic_share",
                                       "pic_damping_time"};
constexpr const char* kPointsKeys[] = {"solid_per_cell", "liquid_per_cell"};
constexpr const char* kInitialKeys[] = {"state", "stress", "rigid_skeleton", "filter_velocity", "undrained_surcharge",
                                        "gravity_stage_duration", "gravity_stage_damping", "gravity_stage_ramp", "porosity_field", "porosity_wave"};
constexpr const char* kPorosityFieldKeys[] = {"standard_deviation", "correlation_length", "seed", "mirror"};
constexpr const char* kPorosityWaveKeys[] = {"amplitude", "wavelength", "direction"};
constexpr const char* kLoadsKeys[] = {"surcharge", "surcharge_ramp_time"};
constexpr const char* kGateKeys[] = {"mode", "flux", "flux_ramp_time"};
constexpr const char* kReservoirKeys[] = {
    "model",       "head",       "head_rate",     "head_schedule", "area",       "area_table",    "tube_diameter",
    "tube_length", "minor_loss", "tube_friction", "openfoam_case", "gate_patch", "reservoir_patch"};
constexpr const char* kCouplingKeys[] = {"scheme", "window", "tolerance", "max_iterations",
                                         "relaxation"};
constexpr const char* kTimeKeys[] = {
    "end", "scheme", "pressure_solver", "courant", "dt", "output_interval", "checkpoint_interval"};
constexpr const char* kMonitorKeys[] = {"name", "elevation", "x", "y"};
constexpr const char* kOutputKeys[] = {"directory", "fields", "progress_interval"};

const TableKeys kRoot = tableKeys("the top level", kRootKeys);
const TableKeys kGrid = tableKeys("[grid]", kGridKeys);
const TableKeys kColumn = tableKeys("[column]", kColumnKeys);
const TableKeys kMaterial = tableKeys("[materials.NAME]", kMaterialKeys);
const TableKeys kPermeability = tableKeys("[materials.NAME.permeability]", kPermeabilityKeys);
const TableKeys kLayer = tableKeys("[[layers]]", kLayerKeys);
const TableKeys kZone = tableKeys("[[layers.zones]]", kZoneKeys);
const TableKeys kLiquid = tableKeys("[liquid]", kLiquidKeys);
const TableKeys kPoints = tableKeys("[points]", kPointsKeys);
const TableKeys kInitial = tableKeys("[initial]", kInitialKeys);
const TableKeys kPorosityField = tableKeys("[initial.porosity_field]", kPorosityFieldKeys);
const TableKeys kPorosityWave = tableKeys("[initial.porosity_wave]", kPorosityWaveKeys);
const TableKeys kLoads = tableKeys("[loads]", kLoadsKeys);
const TableKeys kGate = tableKeys("[gate]", kGateKeys);
const TableKeys kReservoir = tableKeys("[reservoir]", kReservoirKeys);
const TableKeys kCoupling = tableKeys("[coupling]", kCouplingKeys);
const TableKeys kTime = tableKeys("[time]", kTimeKeys);
const TableKeys kMonitor = tableKeys("[[monitors]]", kMonitorKeys);
const TableKeys kOutput = tableKeys("[output]", kOutputKeys);

const TableCatalogue kAllTables = {&kRoot,  &kGrid,      &kColumn,   &kMaterial, &kPermeability,
                                   &kLayer, &kLiquid,    &kPoints,   &kInitial,  &kLoads,
                                   &kGate,  &kReservoir, &kCoupling, &kTime,     &kMonitor,
                                   &kOutput, &kPorosityField, &kPorosityWave};

/// Largest intrinsic permeability accepted (m2). Clean gravel is ~1e-7 m2; larger values are
/// almost always a hydraulic conductivity in m/s typed where kappa in m2 belongs.
constexpr double kMaxPermeability = 1e-6;
/// Smallest viscosity accepted (Pa s); smaller values are a kPa s value (Anura3D's units).
constexpr double kMinViscosity = 1e-6;

// ------------------------------------------------------------------------------------------------
// The strings each choice accepts (docs/case-format.md lists the same).
// ------------------------------------------------------------------------------------------------

const Options<ShapeFunctionKind> kShapeFunctionOptions = {{"linear", ShapeFunctionKind::Linear},
                                                          {"gimp", ShapeFunctionKind::Gimp}};
const Options<GridGeometry> kGeometryOptions = {{"plane", GridGeometry::Plane},
                                                {"axisymmetric", GridGeometry::Axisymmetric}};
const Options<ConstitutiveModelKind> kModelOptions = {
    {"linear_elastic", ConstitutiveModelKind::LinearElastic},
    {"mohr_coulomb", ConstitutiveModelKind::MohrCoulomb}};
const Options<ParticlePhaseModel> kParticlePhaseOptions = {
    {"none", ParticlePhaseModel::None},
    {"foscolo_gibilaro", ParticlePhaseModel::FoscoloGibilaro}};
const Options<PermeabilityMode> kPermeabilityOptions = {
    {"constant", PermeabilityMode::Constant},
    {"kozeny_carman", PermeabilityMode::KozenyCarman},
    {"kozeny_carman_scaled", PermeabilityMode::KozenyCarmanScaled}};
const Options<InitialState> kStateOptions = {{"solid", InitialState::Solid},
                                              {"fluidised", InitialState::Fluidised}};
const Options<InitialStress> kStressOptions = {{"k0", InitialStress::K0},
                                               {"zero", InitialStress::Zero}};
const Options<GateMode> kGateOptions = {
    {"pressure", GateMode::Pressure}, {"flux", GateMode::Flux}, {"closed", GateMode::Closed}};
const Options<bool> kWaveDirectionOptions = {{"vertical", false}, {"lateral", true}};
const Options<SandOverflow> kSandOverflowOptions = {{"carry", SandOverflow::Carry},
                                                    {"stop", SandOverflow::Stop}};
const Options<TubeFriction> kTubeFrictionOptions = {{"smooth_pipe", TubeFriction::SmoothPipe},
                                                    {"laminar", TubeFriction::Laminar}};
const Options<TimeScheme> kTimeSchemeOptions = {{"explicit", TimeScheme::Explicit},
                                                 {"semi_implicit", TimeScheme::SemiImplicit}};
const Options<PressureSolver> kPressureSolverOptions = {{"automatic", PressureSolver::Automatic},
                                                         {"direct", PressureSolver::Direct},
                                                         {"conjugate_gradient", PressureSolver::ConjugateGradient}};
const Options<CouplingKind> kCouplingOptions = {{"explicit", CouplingKind::Explicit},
                                                   {"implicit", CouplingKind::Implicit}};
const Options<ReservoirKind> kReservoirOptions = {{"constant_head", ReservoirKind::ConstantHead},
                                                  {"lumped", ReservoirKind::Lumped},
                                                  {"openfoam", ReservoirKind::OpenFoam}};

/// A horizontal range written `key = [from, to]` (m), within the grid's width, from < to.
std::optional<HorizontalRange> optionalRange(const Section& s, std::string_view key, double width,
                                             const std::string& hint) {
    const toml::node* node = s.find(key);
    if (!node) return std::nullopt;
    auto value = [](const toml::node* n, double& v) {
        if (!n) return false;
        if (const auto* i = n->as_integer()) { v = static_cast<double>(i->get()); return true; }
        if (const auto* f = n->as_floating_point()) { v = f->get(); return true; }
        return false;
    };
    HorizontalRange r;
    const toml::array* a = node->as_array();
    if (!a || a->size() != 2 || !value(a->get(0), r.from) || !value(a->get(1), r.to))
        s.fail(key, "expected two numbers [from, to] in m (" + hint + "), got " + describe(*node));
    const double tol = 1e-12 * width;
    if (!std::isfinite(r.from) || !std::isfinite(r.to) || r.from < -tol || r.to > width + tol || !(r.from < r.to))
        s.fail(key, "range [" + number(r.from) + ", " + number(r.to) + "] m is out of range: expected 0 <= from < to <= " +
                        number(width) + " m, the grid's width (" + hint + ")");
    return r;
}

/// A table of rows written `key = [[x, y], [x, y], ...]`: x strictly increasing (`xName`, in
/// xRange), y in yRange; at least `minRows` rows
std::vector<std::pair<double, double>> optionalRows(const Section& s, std::string_view key, const char* xName,
                                                    const Range& xRange, const char* yName, const Range& yRange,
                                                    std::size_t minRows) {
    std::vector<std::pair<double, double>> rows;
    const toml::node* node = s.find(key);
    if (!node) return rows;
    const std::string form = std::string("[[") + xName + ", " + yName + "], ...] with " + xName + " in " + xRange.unit +
                             " and " + yName + " in " + yRange.unit;
    auto value = [](const toml::node* n, double& v) {
        if (!n) return false;
        if (const auto* i = n->as_integer()) { v = static_cast<double>(i->get()); return true; }
        if (const auto* f = n->as_floating_point()) { v = f->get(); return std::isfinite(v); }
        return false;
    };
    const toml::array* a = node->as_array();
    if (!a || a->size() < minRows)
        s.fail(key, "expected at least " + std::to_string(minRows) + " rows " + form + ", got " + describe(*node));
    for (std::size_t k = 0; k < a->size(); ++k) {
        const toml::array* row = a->get(k)->as_array();
        double x = 0, y = 0;
        if (!row || row->size() != 2 || !value(row->get(0), x) || !value(row->get(1), y))
            s.fail(key, "row " + std::to_string(k + 1) + ": expected two numbers [" + xName + ", " + yName + "] (" + form +
                            "), got " + describe(*a->get(k)));
        if (!xRange.contains(x))
            s.fail(key, "row " + std::to_string(k + 1) + ": " + xName + " = " + number(x) + " " + xRange.unit +
                            " is out of range: expected " + xRange.describe());
        if (!yRange.contains(y))
            s.fail(key, "row " + std::to_string(k + 1) + ": " + yName + " = " + number(y) + " " + yRange.unit +
                            " is out of range: expected " + yRange.describe());
        if (!rows.empty() && !(x > rows.back().first))
            s.fail(key, "row " + std::to_string(k + 1) + ": " + xName + " = " + number(x) + " " + xRange.unit +
                            " does not follow row " + std::to_string(k) + "'s " + number(rows.back().first) +
                            ": the rows' " + xName + " must increase strictly");
        rows.emplace_back(x, y);
    }
    return rows;
}

// ------------------------------------------------------------------------------------------------
// Loader: one function per section, in the order of docs/case-format.md. Each reads its keys on
// their own; a bound one key sets for another's range (dilatancy_angle <= friction_angle, a
// monitor below column.top) is part of that range. The rules between the values of several keys
// (case/CaseRules) are checked once the keys they relate are read.
// ------------------------------------------------------------------------------------------------

class Loader {
public:
    Loader(KeyLocations& where, std::string caseDirectory)
        : where_(where), caseDirectory_(std::move(caseDirectory)) {}

    CaseConfig load(const toml::table& rootTable) {
        const Section root(rootTable, kRoot, kAllTables, where_);
        c_.caseDirectory = caseDirectory_;
        c_.title = root.string("title", "", /*allowEmpty=*/true);
        c_.gravity = root.optionalNumber("gravity", 9.81, nonNegative("m/s2"));
        readGrid(root);
        readLiquid(root);  // before the materials: their permeability check quotes mu and rho_L
        readMaterials(root);
        readLayers(root);
        readColumn(root);  // after the layers: the water level defaults to the sand top
        // The geometry's rules before the keys whose ranges it sets (a monitor lies within
        // [0, column.top]): a top below the water is reported as such, not as a monitor above it.
        validateGeometry(c_, where_);
        readPoints(root);
        readLoads(root);
        readInitial(root);
        readGate(root);
        readReservoir(root);  // after the gate: the reservoir matters only for a pressure gate
        readCoupling(root);
        readTime(root);
        readMonitors(root);
        readOutput(root);
        validateInitialState(c_, where_);
        return c_;
    }

private:
    void readGrid(const Section& root) {
        const Section s = root.subsection("grid", kGrid, true);
        GridConfig& g = c_.grid;
        g.dimension = s.integer("dimension", 1, between(1, false, 3, false));
        g.cellSize = s.requiredNumber("cell_size", positive("m"), "edge of a grid cell");
        g.geometry = s.choice("geometry", GridGeometry::Plane, kGeometryOptions);
        const bool axisymmetric = g.geometry == GridGeometry::Axisymmetric;
        if (axisymmetric && g.dimension != 2)
            s.fail("geometry", "geometry = \"axisymmetric\" is a 2D (r, z) grid: it needs grid.dimension = 2, not " +
                                   std::to_string(g.dimension));
        if (g.dimension >= 2) {
            g.width = s.requiredNumber("width", positive("m"),
                                       axisymmetric ? "the column's radius, required in axisymmetry"
                                                    : "horizontal extent of the grid, required in 2D and 3D");
        } else {
            g.width = s.optionalNumber("width", 0.0, positive("m"), "ignored in 1D");
        }
        if (g.dimension == 3 || axisymmetric) {
            // The square column's cross-section follows from its width, the cylinder's from its
            // radius; a given one must agree.
            const double area = axisymmetric ? kPi * g.width * g.width : g.width * g.width;
            const char* rule = axisymmetric ? "pi width^2 in axisymmetry" : "width^2 in 3D";
            const auto given = s.optionalNumber("cross_section_area", positive("m2"),
                                                std::string("= ") + rule + ", may be left out");
            if (given && std::abs(*given - area) > 1e-9 * area)
                s.fail("cross_section_area", "value " + number(*given) + " m2 disagrees with " +
                                                 (axisymmetric ? "the cylinder's pi width^2 = " : "the 3D column's width^2 = ") +
                                                 number(area) + " m2 (leave it out: " +
                                                 (axisymmetric ? "in axisymmetry" : "in 3D") + " it follows from grid.width)");
            g.crossSectionArea = area;
        } else {
            g.crossSectionArea =
                s.requiredNumber("cross_section_area", positive("m2"), "cross-section of the column");
        }
        g.shapeFunctions =
            s.choice("shape_functions", ShapeFunctionKind::Linear, kShapeFunctionOptions);
    }

    void readLiquid(const Section& root) {
        const Section s = root.subsection("liquid", kLiquid, false);
        LiquidConfig& l = c_.liquid;
        l.density = s.optionalNumber("density", 998.2, positive("kg/m3"));
        // its default follows time.scheme, read later (readTime)
        const std::optional<double> bulkModulus = s.optionalNumber("bulk_modulus", positive("Pa"));
        l.bulkModulusGiven = bulkModulus.has_value();
        l.bulkModulus = bulkModulus.value_or(LiquidConfig::kSoftBulkModulus);
        l.viscosity = s.optionalNumber("viscosity", 8.91e-4, positive("Pa s"));
        if (l.viscosity < kMinViscosity)
            s.fail("viscosity",
                   "value " + number(l.viscosity) +
                       " Pa s is implausibly small (expected >= " + number(kMinViscosity) +
                       " Pa s; water at 20 C: 1.0e-3 Pa s). The unit is Pa s, "
                       "not kPa s as in Anura3D tables: 8.91e-7 kPa s = 8.91e-4 Pa s");
        l.cavitationPressure = s.optionalNumber(
            "cavitation_pressure", 0.0,
            between(-std::numeric_limits<double>::infinity(), false, 0.0, false, "Pa"),
            "a gauge pressure: 0 or a suction");
        l.freeSurfaceZeroPressure = s.boolean("free_surface_zero_pressure", false);
        l.freeSurfaceFilling =
            s.optionalNumber("free_surface_filling", 0.9, between(0, true, 1, false));
        l.gridLiquidMass = s.boolean("grid_liquid_mass", true);
        l.picShare = s.optionalNumber("pic_share", 0.0, between(0, false, 0.5, false),
                                      "a share per step: 0 (FLIP, the verified default) to 0.5; 0.01 is usual");
        if (s.has("pic_damping_time")) {
            if (s.has("pic_share"))
                s.fail("pic_damping_time",
                       "set either pic_share (a share per step) or pic_damping_time (s), not both: they are "
                       "two ways to give the same blend");
            l.picDampingTime = s.optionalNumber("pic_damping_time", 0.0, positive("s"),
                                                "a damping time in seconds; pic_share = 0.01 at a step dt is "
                                                "about dt / 0.01");
        }
    }

    void readMaterials(const Section& root) {
        const toml::node* node = root.find("materials");
        if (!node)
            root.fail("materials",
                      "missing required table [materials]: define at least one "
                      "material as a [materials.NAME] table");
        const toml::table* table = node->as_table();
        if (!table)
            root.fail("materials",
                      "expected a table of materials, one [materials.NAME] header each, got " +
                          describe(*node));
        if (table->empty())
            root.fail("materials", "no material defined: add at least one [materials.NAME] table");
        std::vector<std::pair<std::string, const toml::node*>> entries;
        for (const auto& [key, value] : *table)
            entries.emplace_back(std::string(key.str()), &value);
        std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
            return lineOfNode(*a.second) < lineOfNode(*b.second);
        });
        for (const auto& [name, value] : entries) {
            const std::string path = "materials." + name;
            if (!value->is_table())
                throw InputError(
                    where_.file(), lineOfNode(*value) > 0 ? lineOfNode(*value) : root.lineOf("materials"),
                    path,
                    "expected a table [" + path + "] describing a material, got " +
                        describe(*value) + "; material keys go under a [materials.NAME] header");
            const Section s = root.child(*value->as_table(), path, kMaterial, root.lineOf("materials"));
            c_.materials.push_back(readMaterial(s, name));
        }
    }

    MaterialConfig readMaterial(const Section& s, const std::string& name) const {
        MaterialConfig m;
        m.name = name;
        m.model = s.choice("model", ConstitutiveModelKind::LinearElastic, kModelOptions);
        m.grainDensity = s.optionalNumber("grain_density", 2650.0, positive("kg/m3"));
        if (m.grainDensity < kMinGrainDensity)
            s.fail("grain_density", "value " + number(m.grainDensity) + " kg/m3 is implausibly small (expected >= " +
                                        number(kMinGrainDensity) +
                                        " kg/m3; quartz sand: 2650 kg/m3). The unit is kg/m3, not g/cm3: 2.65 g/cm3 = "
                                        "2650 kg/m3");
        m.porosity = s.requiredNumber("porosity", between(0, true, 1, true),
                                      "initial porosity n0, a fraction: 0.38, not 38");
        m.maxPorosity = s.optionalNumber("max_porosity", 0.41, between(0, true, 1, true));
        m.minPorosity = s.optionalNumber("min_porosity", 0.32, between(0, true, 1, true));
        if (m.minPorosity < kMinMinPorosity)
            s.fail("min_porosity", "value " + number(m.minPorosity) + " is implausibly small (expected >= " +
                                       number(kMinMinPorosity) +
                                       "; sands pack no denser than about 0.2, equal spheres 0.26): the free water "
                                       "gets ceil(points.liquid_per_cell / min_porosity) points per cell height");
        m.youngsModulus = s.optionalNumber("youngs_modulus", 1e6, positive("Pa"));
        m.poissonRatio = s.optionalNumber("poisson_ratio", 0.3, between(0, false, 0.5, true));
        if (m.model == ConstitutiveModelKind::MohrCoulomb) {
            m.frictionAngle =
                s.optionalNumber("friction_angle", 30.0, between(0, true, 90, true, "deg"));
            m.dilatancyAngle = s.optionalNumber("dilatancy_angle", 0.0,
                                                between(0, false, m.frictionAngle, false, "deg"),
                                                "at most friction_angle");
            m.cohesion = s.optionalNumber("cohesion", 0.0, nonNegative("Pa"));
            const double apex = m.cohesion / std::tan(m.frictionAngle * kPi / 180.0);
            m.tensileStrength = s.optionalNumber("tensile_strength", 0.0, between(0, false, apex, false, "Pa"),
                                                 "at most the apex c cot(phi) = " + number(apex) + " Pa");
        } else {
            for (const char* key : {"friction_angle", "dilatancy_angle", "cohesion", "tensile_strength"})
                s.forbid(key, "it is a Mohr-Coulomb constant and model is " +
                                  nameOf(kModelOptions, m.model) + " (set model = \"mohr_coulomb\" to use it)");
        }
        m.k0 = s.optionalNumber("k0", 0.5, nonNegative(""));
        m.ergun = s.boolean("ergun", true);
        m.ergunA = s.optionalNumber("ergun_a", 150.0, positive(""));
        m.ergunB = s.optionalNumber("ergun_b", 1.75, nonNegative(""));
        m.permeability = readPermeability(s.subsection("permeability", kPermeability, true));
        readParticlePhase(s, m);
        m.closePacking = s.boolean("close_packing", false);
        return m;
    }

    // The fluidised sand's particle phase, and how much of the grid's front diffusion is kept
    void readParticlePhase(const Section& s, MaterialConfig& m) const {
        m.particlePhase = s.choice("particle_phase", ParticlePhaseModel::None, kParticlePhaseOptions);
        m.frontDiffusion = s.optionalNumber("front_diffusion", 0.25, between(0, false, 1, false, ""),
                                            "alpha of D = alpha h c, 0.25 by default, 0 to turn it off");
        m.frontThreshold = s.optionalNumber("front_threshold", 0.0, between(0, false, 0.5, false, ""),
                                            "the porosity change over a cell below which the front diffusion "
                                            "fades, e.g. 0.01; 0 (the default) keeps it everywhere");
        if (m.particlePhase == ParticlePhaseModel::None) {
            s.forbid("particle_grain_size", "it is Foscolo and Gibilaro's grain size, and particle_phase is \"none\" "
                                            "(set particle_phase = \"foscolo_gibilaro\" to use it)");
            return;
        }
        const bool kozenyCarman = m.permeability.mode == PermeabilityMode::KozenyCarman;
        if (kozenyCarman)
            m.particleGrainSize = s.optionalNumber("particle_grain_size", m.permeability.grainSize, positive("m"),
                                                   "the grains' size in m (default: the permeability's grain_size)");
        else
            m.particleGrainSize = s.requiredNumber("particle_grain_size", positive("m"),
                                                   "the grains' size d in m, e.g. 0.261 mm = 2.61e-4 m (Foscolo and "
                                                   "Gibilaro's modulus 3.2 g d (1 - n)(rho_s - rho_L))");
        if (m.particleGrainSize > 0.05)
            s.fail("particle_grain_size", "value " + number(m.particleGrainSize) +
                                              " m is not a grain's size (expected > 0 and <= 0.05 m). The unit is m, "
                                              "not mm: 0.261 mm = 2.61e-4 m");
    }

    PermeabilityConfig readPermeability(const Section& s) const {
        PermeabilityConfig p;
        p.mode = s.requiredChoice("mode", kPermeabilityOptions);
        if (p.mode == PermeabilityMode::KozenyCarman) {
            s.forbid("value",
                     "mode = \"kozeny_carman\" computes kappa from grain_size (to scale a "
                     "given kappa with porosity use mode = \"kozeny_carman_scaled\")");
            p.grainSize = s.requiredNumber("grain_size", positive("m"),
                                           "grain size D in m, e.g. D10 = 0.261 mm = 2.61e-4 m");
            return p;
        }
        s.forbid("grain_size", "it is used only with mode = \"kozeny_carman\" (mode is " +
                                   nameOf(kPermeabilityOptions, p.mode) + ")");
        p.value = s.requiredNumber("value", positive("m2"), "intrinsic permeability kappa in m2");
        if (p.value > kMaxPermeability) {
            const LiquidConfig& l = c_.liquid;
            const double g = c_.gravity > 0.0 ? c_.gravity : 9.81;
            const double kappa = p.value * l.viscosity / (l.density * g);
            s.fail("value",
                   "value " + number(p.value) +
                       " is far too large for an intrinsic permeability in m2 "
                       "(expected > 0 and <= " +
                       number(kMaxPermeability) +
                       " m2; clean gravel is about "
                       "1e-7 m2). It looks like a hydraulic conductivity K in m/s. The intrinsic "
                       "permeability is kappa = K mu / (rho_L g): here " +
                       number(p.value) + " * " + number(l.viscosity) + " / (" + number(l.density) +
                       " * " + number(g) + ") = " + number(kappa, 4) + " m2. Give kappa in m2");
        }
        return p;
    }

    void readLayers(const Section& root) {
        const toml::array* layers = root.arrayOfTables("layers", true);
        std::vector<std::string> names;
        for (const MaterialConfig& m : c_.materials) names.push_back(m.name);
        for (std::size_t i = 0; i < layers->size(); ++i) {
            const Section s = root.entry("layers", i, kLayer);
            LayerConfig layer;
            layer.material = s.requiredString("material", "the NAME of a [materials.NAME] table");
            if (std::find(names.begin(), names.end(), layer.material) == names.end()) {
                std::string what = "no material named " + inQuotes(layer.material) +
                                   " in [materials]; defined: " + joinQuoted(names);
                if (auto guess = nearest(layer.material, names))
                    what += ". Did you mean " + inQuotes(*guess) + "?";
                s.fail("material", what);
            }
            layer.thickness = s.requiredNumber("thickness", positive("m"));
            readZones(s, names, layer);
            c_.layers.push_back(layer);
        }
    }

    /// [[layers.zones]]: parts of a layer made of another material, side by side with it.
    void readZones(const Section& layer, const std::vector<std::string>& names, LayerConfig& out) {
        const toml::array* zones = layer.arrayOfTables("zones", false);
        if (!zones) return;
        // A rule between keys, but it decides whether the zones are read at all (a 1D grid has no
        // width to place them in), so it is the schema's, like a key that does not apply.
        if (c_.grid.dimension == 1)
            layer.fail("zones", "zones place materials side by side, which needs grid.dimension = 2 or 3 "
                                "(a 1D column has one material per layer)");
        for (std::size_t i = 0; i < zones->size(); ++i) {
            const Section s = layer.entry("zones", i, kZone);
            ZoneConfig z;
            z.material = s.requiredString("material", "the NAME of a [materials.NAME] table");
            if (std::find(names.begin(), names.end(), z.material) == names.end()) {
                std::string what = "no material named " + inQuotes(z.material) + " in [materials]; defined: " +
                                   joinQuoted(names);
                if (auto guess = nearest(z.material, names)) what += ". Did you mean " + inQuotes(*guess) + "?";
                s.fail("material", what);
            }
            const std::string hint = "the zone's horizontal extent";
            if (!s.has("x")) s.missing("x", "[from, to] in m, " + hint);
            z.x = *optionalRange(s, "x", c_.grid.width, hint);
            if (c_.grid.dimension == 3) z.y = optionalRange(s, "y", c_.grid.width, hint + " along y");
            else s.forbid("y", "y applies only in 3D (grid.dimension = 3)");
            out.zones.push_back(z);
        }
    }

    void readColumn(const Section& root) {
        const Section s = root.subsection("column", kColumn, true);
        ColumnConfig& col = c_.column;
        col.chamberHeight = s.requiredNumber(
            "chamber_height", positive("m"),
            "height of the free-water chamber from the gate (z = 0) to the filter");
        col.waterLevel = s.optionalNumber("water_level", c_.sandTop(), anyValue("m"));
        col.overflowLevel = s.optionalNumber("overflow_level", anyValue("m"));
        col.sandOverflow = s.choice("sand_overflow", SandOverflow::Carry, kSandOverflowOptions);
        col.top = s.requiredNumber("top", positive("m"),
                                   "top of the grid, above water and overflow levels");
        if (c_.grid.dimension == 1)
            s.forbid("wall_friction_angle", "a 1D column has no lateral walls (grid.dimension = 1)");
        else
            col.wallFrictionAngle = s.optionalNumber("wall_friction_angle", 0.0, between(0, false, 90, true, "deg"));
    }

    void readPoints(const Section& root) {
        const Section s = root.subsection("points", kPoints, false);
        c_.points.solidPerCell = s.integer("solid_per_cell", 2, between(1, false, 8, false));
        c_.points.liquidPerCell = s.integer("liquid_per_cell", 2, between(1, false, 8, false));
    }

    void readLoads(const Section& root) {
        const Section s = root.subsection("loads", kLoads, false);
        c_.loads.surcharge = s.optionalNumber("surcharge", 0.0, nonNegative("Pa"));
        c_.loads.surchargeRampTime = s.optionalNumber("surcharge_ramp_time", 0.0, nonNegative("s"));
    }

    void readInitial(const Section& root) {
        const Section s = root.subsection("initial", kInitial, false);
        InitialConfig& i = c_.initial;
        i.state = s.choice("state", InitialState::Solid, kStateOptions);
        // Which keys apply to a bed that starts fluidised: the schema's, as they decide what is
        // read (the stress of a suspension is zero whatever the file says).
        if (i.state == InitialState::Fluidised) {
            // a suspension carries no effective stress: its weight rests on the pore water
            if (s.has("stress") && s.choice("stress", InitialStress::Zero, kStressOptions) != InitialStress::Zero)
                s.fail("stress", "a bed that starts fluidised (state = \"fluidised\") carries no effective "
                                 "stress; remove 'stress' or set stress = \"zero\"");
            i.stress = InitialStress::Zero;
            s.forbid("rigid_skeleton", "a fluidised bed cannot have a rigid skeleton");
            s.forbid("undrained_surcharge", "a fluidised bed carries no surcharge on its skeleton");
        } else {
            i.stress = s.choice("stress", InitialStress::K0, kStressOptions);
        }
        i.rigidSkeleton = s.boolean("rigid_skeleton", false);
        i.filterVelocity = s.optionalNumber(
            "filter_velocity", 0.0,
            between(-std::numeric_limits<double>::infinity(), false, std::numeric_limits<double>::infinity(), false, "m/s"),
            "upward filter velocity q0 of an initial steady seepage, m/s");
        i.undrainedSurcharge = s.boolean("undrained_surcharge", false);
        i.gravityStageDuration = s.optionalNumber("gravity_stage_duration", 0.0, nonNegative("s"));
        i.gravityStageDamping =
            s.optionalNumber("gravity_stage_damping", 0.05, between(0, false, 1, true));
        i.gravityStageRamp = s.optionalNumber(
            "gravity_stage_ramp", 0.0, between(0, false, i.gravityStageDuration, false, "s"),
            "time over which the grains' buoyant weight rises from zero, within gravity_stage_duration");
        if (s.has("porosity_field")) {
            if (i.state == InitialState::Fluidised)
                s.fail("porosity_field", "a bed that starts fluidised has no porosity of its own to vary "
                                         "(remove porosity_field or start with state = \"solid\")");
            const Section f = s.subsection("porosity_field", kPorosityField, true);
            PorosityFieldConfig& p = i.porosityField;
            p.enabled = true;
            p.standardDeviation = f.requiredNumber("standard_deviation", between(0, false, 0.1, false),
                                                   "standard deviation of the porosity (-), e.g. 0.01");
            p.correlationLength = f.requiredNumber("correlation_length", positive("m"),
                                                   "distance over which the porosity is alike, m");
            p.seed = static_cast<std::uint64_t>(f.integer("seed", 1, between(0, false, 2147483647.0, false)));
            p.mirror = f.boolean("mirror", false);
            if (p.mirror && (c_.grid.dimension == 1 || c_.grid.geometry == GridGeometry::Axisymmetric))
                f.fail("mirror", "a mirror image across the column's mid-plane x = width/2 needs a 2D plane or a 3D grid "
                                 "(this one is " + std::string(c_.grid.dimension == 1 ? "1D" : "axisymmetric") +
                                     "); remove mirror");
        }
        if (s.has("porosity_wave")) {
            const Section f = s.subsection("porosity_wave", kPorosityWave, true);
            PorosityWaveConfig& w = i.porosityWave;
            w.enabled = true;
            w.amplitude = f.requiredNumber("amplitude", between(0, true, 0.05, false),
                                           "amplitude of the porosity's sine (-), e.g. 1e-3");
            w.wavelength = f.requiredNumber("wavelength", positive("m"), "the sine's wavelength, m");
            w.lateral = f.choice("direction", false, kWaveDirectionOptions);
            if (w.lateral && c_.grid.dimension == 1)
                f.fail("direction", "a lateral wave needs a 2D or 3D grid (grid.dimension = 1)");
        }
    }

    void readGate(const Section& root) {
        const Section s = root.subsection("gate", kGate, false);
        GateConfig& g = c_.gate;
        g.mode = s.choice("mode", GateMode::Pressure, kGateOptions);
        // the mode decides which keys are read (and a key given for another mode is an error)
        if (g.mode == GateMode::Flux) {
            g.flux =
                s.requiredNumber("flux", anyValue("m/s"),
                                 "liquid velocity at the gate, positive upward into the column");
            g.fluxRampTime = s.optionalNumber("flux_ramp_time", 0.0, nonNegative("s"));
        } else {
            const std::string why = "it is used only with mode = \"flux\" (mode is " +
                                    nameOf(kGateOptions, g.mode) + ")";
            s.forbid("flux", why);
            s.forbid("flux_ramp_time", why);
        }
    }

    void readReservoir(const Section& root) {
        const bool pressureGate = c_.gate.mode == GateMode::Pressure;
        if (pressureGate && !root.has("reservoir"))
            root.fail("reservoir",
                      "missing required table [reservoir]: with gate.mode = \"pressure\" "
                      "(the default) the reservoir sets the gate pressure; give at "
                      "least reservoir.head");
        const Section s = root.subsection("reservoir", kReservoir, false);
        ReservoirConfig& r = c_.reservoir;
        r.kind = s.choice("model", ReservoirKind::ConstantHead, kReservoirOptions);
        const std::string notHere =
            "it does not apply to model = " + nameOf(kReservoirOptions, r.kind);
        const Range head = nonNegative("m");
        const std::string headHint =
            "elevation of the reservoir surface above the gate plane z = 0";
        auto readHead = [&] {
            // A flux or closed gate does not use the reservoir: its head may then be left out.
            r.head = pressureGate ? s.requiredNumber("head", head, headHint)
                                  : s.optionalNumber("head", 0.0, head, headHint);
        };
        // the plan area: one number, or a table by level (reservoir/ReservoirShape.hpp)
        auto readArea = [&] {
            r.areaTable = optionalRows(s, "area_table", "level", nonNegative("m"), "area", positive("m2"), 2);
            if (r.areaTable.empty()) {
                r.area = s.requiredNumber("area", positive("m2"),
                                          "plan area of the reservoir (its level balance), or area_table");
                return;
            }
            s.forbid("area", "area_table gives the plan area at every level; use one or the other");
            if (r.head < r.areaTable.front().first)
                s.fail("area_table", "the first row's level " + number(r.areaTable.front().first) +
                                         " m is above the initial head " + number(r.head) +
                                         " m: the table must reach down to the reservoir's level (to the "
                                         "tailwater, for a run that drains it)");
            r.area = PiecewiseLinear(r.areaTable)(r.head);  // the area at the start, for reports
        };
        switch (r.kind) {
            case ReservoirKind::ConstantHead:
                for (const char* key : {"area", "area_table", "tube_diameter", "tube_length", "minor_loss",
                                        "tube_friction", "openfoam_case", "gate_patch", "reservoir_patch"})
                    s.forbid(key, notHere);
                r.headSchedule = optionalRows(s, "head_schedule", "time", nonNegative("s"), "head", head, 1);
                if (!r.headSchedule.empty()) {
                    const std::string why = "head_schedule gives the head at every time (its first row's head is the "
                                            "initial one); use one or the other";
                    s.forbid("head", why);
                    s.forbid("head_rate", why);
                    r.head = r.headSchedule.front().second;
                    break;
                }
                readHead();
                r.headRate = s.optionalNumber("head_rate", 0.0, anyValue("m/s"));
                break;
            case ReservoirKind::Lumped:
                for (const char* key :
                     {"head_rate", "head_schedule", "openfoam_case", "gate_patch", "reservoir_patch"})
                    s.forbid(key, notHere + " (the level follows the flux; a scheduled head is model = \"constant_head\")");
                readHead();
                readArea();
                r.tubeDiameter =
                    s.optionalNumber("tube_diameter", 0.0, nonNegative("m"), "0: no tube");
                if (r.tubeDiameter > 0.0) {
                    r.tubeLength =
                        s.requiredNumber("tube_length", positive("m"),
                                         "length of the U-tube, required with tube_diameter > 0");
                    r.minorLoss = s.optionalNumber("minor_loss", 0.0, nonNegative(""));
                    r.tubeFriction = s.choice("tube_friction", TubeFriction::SmoothPipe, kTubeFrictionOptions);
                } else {
                    s.forbid(
                        "tube_length",
                        "there is no tube (tube_diameter = 0; give tube_diameter > 0 for one)");
                    s.forbid("minor_loss",
                             "minor losses act in the tube and there is none "
                             "(tube_diameter = 0; give tube_diameter > 0 for one)");
                    s.forbid("tube_friction",
                             "there is no tube (tube_diameter = 0; give tube_diameter > 0 for one)");
                }
                break;
            case ReservoirKind::OpenFoam: {
                for (const char* key : {"head_rate", "head_schedule", "tube_diameter", "tube_length", "minor_loss", "tube_friction"})
                    s.forbid(key, notHere + " (the OpenFOAM case holds the tube)");
                readHead();
                readArea();
                const std::string given = s.requiredString(
                    "openfoam_case",
                    "the path of the OpenFOAM case directory, relative to the case directory");
                std::filesystem::path path(given);
                if (path.is_relative()) path = std::filesystem::path(caseDirectory_) / path;
                path = std::filesystem::absolute(path).lexically_normal();
                if (!std::filesystem::is_directory(path))
                    s.fail("openfoam_case", "OpenFOAM case directory " + inQuotes(path.string()) +
                                                " does not exist (" + inQuotes(given) +
                                                " is read relative to the case directory " +
                                                inQuotes(caseDirectory_) + ")");
                r.openfoamCase = path.string();
                r.gatePatch = s.string("gate_patch", "gate");
                r.reservoirPatch = s.string("reservoir_patch", "reservoir");
                break;
            }
        }
    }

    void readTime(const Section& root) {
        const Section s = root.subsection("time", kTime, true);
        TimeConfig& t = c_.time;
        t.end = s.requiredNumber("end", positive("s"), "simulated end time");
        t.scheme = s.choice("scheme", TimeScheme::Explicit, kTimeSchemeOptions);
        // the water a scheme is meant for: soft for the explicit step, real for the semi-implicit
        if (!c_.liquid.bulkModulusGiven)
            c_.liquid.bulkModulus = t.scheme == TimeScheme::SemiImplicit ? LiquidConfig::kRealBulkModulus
                                                                         : LiquidConfig::kSoftBulkModulus;
        t.pressureSolver = s.choice("pressure_solver", PressureSolver::Automatic, kPressureSolverOptions);
        t.courant = s.optionalNumber("courant", 0.4, between(0, true, 0.5, false));
        t.dt = s.optionalNumber("dt", positive("s"));
        t.outputInterval = s.optionalNumber("output_interval", t.end / 100.0, positive("s"));
        t.checkpointInterval =
            s.optionalNumber("checkpoint_interval", 0.0, nonNegative("s"), "0: only at the end");
    }

    void readMonitors(const Section& root) {
        const toml::array* monitors = root.arrayOfTables("monitors", false);
        if (!monitors) return;
        std::vector<int> lines;
        for (std::size_t i = 0; i < monitors->size(); ++i) {
            const Section s = root.entry("monitors", i, kMonitor);
            MonitorConfig m;
            m.name = s.requiredString("name", "a unique name for the monitor");
            // names head the columns of series.csv, so they must differ; checked as they are
            // read, since the message quotes the line of the first monitor of that name
            for (std::size_t j = 0; j < c_.monitors.size(); ++j)
                if (c_.monitors[j].name == m.name)
                    s.fail("name", "monitor name " + inQuotes(m.name) +
                                       " is already used by monitors[" + std::to_string(j) +
                                       "] (line " + std::to_string(lines[j]) +
                                       "); monitor names must be unique");
            m.elevation =
                s.requiredNumber("elevation", between(0, false, c_.column.top, false, "m"),
                                 "within the grid, from the gate (0) to column.top");
            const std::string part = "the part of the section to average over";
            if (c_.grid.dimension == 1) {
                s.forbid("x", "a 1D section has no horizontal extent");
                s.forbid("y", "a 1D section has no horizontal extent");
            } else {
                m.x = optionalRange(s, "x", c_.grid.width, part);
                if (c_.grid.dimension == 3) m.y = optionalRange(s, "y", c_.grid.width, part + " along y");
                else s.forbid("y", "y applies only in 3D (grid.dimension = 3)");
            }
            c_.monitors.push_back(m);
            lines.push_back(s.line());
        }
    }

    void readCoupling(const Section& root) {
        if (c_.reservoir.kind != ReservoirKind::OpenFoam) {
            if (root.has("coupling"))
                root.fail("coupling", "[coupling] applies only to reservoir.model = \"openfoam\" "
                                      "(the built-in reservoirs are advanced every MPM step)");
            return;
        }
        const Section s = root.subsection("coupling", kCoupling, false);
        CouplingConfig& k = c_.coupling;
        k.scheme = s.choice("scheme", CouplingKind::Implicit, kCouplingOptions);
        k.window = s.optionalNumber("window", 1e-3, positive("s"), "the CFD time step");
        const bool implicit = k.scheme == CouplingKind::Implicit;
        const std::string why = "it applies only to scheme = \"implicit\"";
        if (implicit) {
            k.tolerance = s.optionalNumber("tolerance", 1e-3, between(0, false, 1, false));
            k.maxIterations = s.integer("max_iterations", 30, between(1, false, 1000, false));
            k.relaxation = s.optionalNumber("relaxation", 0.5, between(0, false, 1, true));
        } else {
            for (const char* key : {"tolerance", "max_iterations", "relaxation"}) s.forbid(key, why);
        }
    }

    void readOutput(const Section& root) {
        const Section s = root.subsection("output", kOutput, false);
        c_.output.directory = s.string("directory", "output");
        c_.output.fields = s.boolean("fields", true);
        c_.output.progressInterval = s.optionalNumber("progress_interval", 2.0, positive("s"));
    }

    KeyLocations& where_;
    std::string caseDirectory_;
    CaseConfig c_;
};

}  // namespace

namespace {

/// An error the schema found, placed at the override that caused it: its key, or a key under it
/// (a table set whole); an error elsewhere, in a case with overrides, lists them
[[noreturn]] void blameOverride(const InputError& e, const std::vector<CaseOverride>& overrides) {
    // the override of that very key first (the last one given wins, as in the file), then one
    // under it (a key of a table the override set whole)
    const CaseOverride* culprit = nullptr;
    for (const CaseOverride& o : overrides)
        if (e.key() == o.key) culprit = &o;
    if (!culprit)
        for (const CaseOverride& o : overrides)
            if (e.key().rfind(o.key + ".", 0) == 0) culprit = &o;
    // or the table an override made, misnamed (--set reservior.area=1: the unknown key is
    // 'reservior'), which only an override can have put there
    if (!culprit)
        for (const CaseOverride& o : overrides)
            if (o.key.rfind(e.key() + ".", 0) == 0 && e.detail().rfind("unknown key", 0) == 0) culprit = &o;
    if (culprit) throw InputError(e.file() + ", " + culprit->text(), 0, e.key(), e.detail());
    std::string with;
    for (const CaseOverride& o : overrides) with += (with.empty() ? "" : ", ") + o.text();
    throw InputError(e.file(), e.line(), e.key(), e.detail() + " (with " + with + ")");
}

}  // namespace

CaseConfig parseCase(const std::string& tomlText, const std::string& fileName,
                     const std::string& caseDirectory, const std::vector<CaseOverride>& overrides) {
    toml::table root;
#if TOML_EXCEPTIONS
    try {
        root = toml::parse(std::string_view(tomlText), std::string_view(fileName));
    } catch (const toml::parse_error& e) {
        throw InputError(fileName, static_cast<int>(e.source().begin.line), "",
                         "TOML syntax error: " + std::string(e.description()));
    }
#else
    toml::parse_result result = toml::parse(std::string_view(tomlText), std::string_view(fileName));
    if (!result)
        throw InputError(fileName, static_cast<int>(result.error().source().begin.line), "",
                         "TOML syntax error: " + std::string(result.error().description()));
    root = std::move(result).table();
#endif
    const std::vector<OverrideSite> sites = applyOverrides(root, overrides, fileName);
    KeyLocations where(fileName);
    CaseConfig config;
    try {
        config = Loader(where, caseDirectory).load(root);
    } catch (const InputError& e) {
        if (overrides.empty()) throw;
        blameOverride(e, overrides);
    }
    config.overrides = overrides;
    // without overrides the file itself, comments and all
    config.effectiveCase = overrides.empty() ? tomlText : effectiveCaseText(tomlText, root, overrides, sites, fileName);
    return config;
}

CaseConfig loadCase(const std::string& caseDirectory, const std::vector<CaseOverride>& overrides) {
    const std::filesystem::path file = std::filesystem::path(caseDirectory) / "case.toml";
    if (std::filesystem::is_directory(file))
        throw InputError(file.string(), 0, "",
                         "is a directory, not a file: the case file case.toml must be a TOML file");
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        const std::string why =
            std::filesystem::is_directory(caseDirectory)
                ? "cannot read the case file (a case directory must hold case.toml)"
                : "cannot read the case file: case directory " + inQuotes(caseDirectory) +
                      " does not exist";
        throw InputError(file.string(), 0, "", why);
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parseCase(text.str(), file.string(), caseDirectory, overrides);
}

}  // namespace qs
