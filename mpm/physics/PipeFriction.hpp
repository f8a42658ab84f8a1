#pragma once
// PipeFriction: the Darcy friction factor f of a smooth pipe, whose head loss over a length L of
// diameter d at mean velocity U is h_f = f (L/d) U^2 / (2 g), at Reynolds number Re = U d / nu.
//
//   laminar (Hagen-Poiseuille)   f = 64 / Re
//   Blasius (turbulent, smooth)  f = 0.316 Re^(-1/4)                    4e3 < Re < 1e5
//   Colebrook (smooth)           1/sqrt(f) = -2 log10(2.51 / (Re sqrt(f)))   turbulent
//   Churchill (1977)             f = 8 [(8/Re)^12 + (A + B)^(-3/2)]^(1/12), all regimes:
//                                A = [2.457 ln(1 / ((7/Re)^0.9 + 0.27 eps/d))]^16, B = (37530/Re)^16
//
// Churchill's one formula is laminar below Re ~ 2000 (64/Re to 1e-12 at Re = 1000), bridges the
// transition smoothly and follows Colebrook in turbulent flow (within 1.7 % for smooth pipes
// from Re = 4000, 0.4 % from 1e4; tested), so a model that uses it has no switch for a solver to chatter on. A lumped tube uses it
// as a multiplier on the Hagen-Poiseuille loss, frictionMultiplier(Re) = f Re / 64 (1 in laminar
// flow), which stays finite as the flow stops.
namespace qs::friction {

double laminar(double reynolds);
double blasius(double reynolds);
/// Colebrook's smooth-pipe law, solved by fixed-point iteration to round-off.
double colebrookSmooth(double reynolds);
/// Churchill's all-regime law for a pipe of relative roughness eps/d (0: smooth).
double churchill(double reynolds, double relativeRoughness = 0.0);
/// f Re / 64 of Churchill's law for a smooth pipe: the loss over the laminar one (1 as Re -> 0).
double frictionMultiplier(double reynolds);
/// s/m2, the head a laminar flow loses per flow rate in a tube, h_f / Q: the laminar f = 64/Re in
/// h_f = f (L/d) U^2/(2g) gives h_f = 32 nu L U / (g d^2), with U = Q / (pi d^2 / 4). The
/// reservoirs' tube loss (the tests check it against physics/ClosedForms' Hagen-Poiseuille form).
double laminarHeadPerFlow(double diameter, double length, double liquidDensity, double gravity, double viscosity);

}  // namespace qs::friction
