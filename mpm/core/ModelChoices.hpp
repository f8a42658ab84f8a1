#pragma once
// ModelChoices: the choices a case makes between models and methods (shape functions, geometry,
// permeability law, time scheme, ...), below the case schema (case/CaseConfig.hpp) so that the
// grid and the physics can name a choice without depending on how a case is read.
namespace qs {

enum class ShapeFunctionKind { Linear, Gimp };
/// plane: 2D plane strain (or 1D, 3D); axisymmetric: 2D (r, z), the column a cylinder of radius width
enum class GridGeometry { Plane, Axisymmetric };
enum class PermeabilityMode { Constant, KozenyCarman, KozenyCarmanScaled };
enum class ConstitutiveModelKind { LinearElastic, MohrCoulomb };
/// The fluidised sand's particle phase (physics/ParticlePhase.hpp): none, or Foscolo and Gibilaro's.
enum class ParticlePhaseModel { None, FoscoloGibilaro };
enum class InitialStress { K0, Zero };
enum class InitialState { Solid, Fluidised };
enum class GateMode { Pressure, Flux, Closed };
/// How a step advances the nodes' velocities and the pore pressure (solver/TimeIntegrator.hpp):
/// all explicit, bounded by the water's compression wave, or with the pressure implicit
/// (a projection), bounded by the skeleton's wave only.
enum class TimeScheme { Explicit, SemiImplicit };
/// The semi-implicit step's linear solver (solver/PressureSystem.hpp): the direct one up to
/// 20 000 cells and conjugate gradients beyond (Automatic), or either always.
enum class PressureSolver { Automatic, Direct, ConjugateGradient };
/// What sand reaching the overflow level does: leaves with the water, or stops the run.
enum class SandOverflow { Carry, Stop };
enum class ReservoirKind { ConstantHead, Lumped, OpenFoam };
enum class CouplingKind { Explicit, Implicit };
/// The lumped tube's wall friction: Hagen-Poiseuille only, or a smooth pipe in every regime.
enum class TubeFriction { SmoothPipe, Laminar };

}  // namespace qs
