#include "solver/ColumnBuilder.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/Error.hpp"
#include "materials/StressTensor.hpp"
#include "physics/DragLaw.hpp"
#include "physics/Permeability.hpp"
#include "core/Constants.hpp"
#include "physics/RandomPorosityField.hpp"
#include "solver/DoublePointSolver.hpp"

namespace qs {

namespace {

/// Calls emit(x, V) for a regular lattice filling the slab z0 < z < z1: `perCell` points per
/// horizontal axis in every cell, nz layers along the vertical. V is the volume the point stands
/// for (in axisymmetry the ring 2 pi r around the axis).
template <int D, class F>
void forEachLatticePoint(const Grid<D>& grid, int perCell, Real z0, Real z1, Index nz, F&& emit) {
    Index nh = 1;
    for (int d = 0; d < D - 1; ++d) nh *= grid.cells(d) * perCell;
    const Real dz = (z1 - z0) / nz;
    const Real spacing = grid.h() / perCell;
    Vec<D> x;
    for (Index iz = 0; iz < nz; ++iz) {
        for (Index ih = 0; ih < nh; ++ih) {
            Index rest = ih;
            for (int d = 0; d < D - 1; ++d) {
                const Index n = grid.cells(d) * perCell;
                x[d] = (rest % n + 0.5) * spacing;
                rest /= n;
            }
            x[D - 1] = z0 + (iz + 0.5) * dz;
            emit(x, grid.pointFootprint(&x[0], perCell) * dz);
        }
    }
}

template <int D>
void appendSolid(SolidPoints<D>& s, const Vec<D>& x, Real V, Real n, Real rhoS, int material,
                 const Real* stress, int state) {
    for (int d = 0; d < D; ++d) { s.x.push_back(x[d]); s.v.push_back(0); }
    s.mass.push_back((1 - n) * rhoS * V);
    s.volume.push_back(V);
    s.porosity.push_back(n);
    for (int k = 0; k < 6; ++k) s.stress.push_back(stress[k]);
    s.state.push_back(state);
    s.material.push_back(material);
    for (int k = 0; k < s.internalCount; ++k) s.internal.push_back(0);
    for (int k = 0; k < D * D; ++k) s.velocityGradient.push_back(0);
}

template <int D>
void appendLiquid(LiquidPoints<D>& l, const Vec<D>& x, Real V, Real mass, Real p, Real verticalVelocity) {
    for (int d = 0; d < D; ++d) { l.x.push_back(x[d]); l.v.push_back(d == D - 1 ? verticalVelocity : 0); }
    l.mass.push_back(mass);
    l.volume.push_back(V);
    l.pressure.push_back(p);
    l.state.push_back(kSubmergedLiquid);
    l.cavity.push_back(0);
}

Index cellsIn(Real length, Real h) { return static_cast<Index>(std::llround(length / h)); }

}  // namespace

int freeWaterPointsPerCell(const CaseConfig& config) {
    Real nMin = 1.0;
    for (const auto& m : config.materials) nMin = std::min(nMin, m.minPorosity);
    // the loader keeps n_min >= 0.05; the bound keeps the conversion defined for any config
    const Real perCell = std::ceil(config.points.liquidPerCell / nMin - 1e-9);
    return perCell < 1e6 ? static_cast<int>(perCell) : 1000000;
}

template <int D>
void buildColumn(const CaseConfig& config, const Grid<D>& grid,
                 const std::vector<SolidMaterial>& materials, SolidPoints<D>& solid,
                 LiquidPoints<D>& liquid, const std::function<bool(const Real* x)>& keep) {
    auto made = [&](const Vec<D>& x) { return !keep || keep(&x[0]); };
    const Real h = grid.h();
    const Real g = config.gravity;
    const Real rhoL = config.liquid.density;
    const Real zWater = config.column.waterLevel;
    const int spc = config.points.solidPerCell, lpc = config.points.liquidPerCell;
    // uGIMP half-lengths from the finest spacing of each set: free-water liquid points sit closer
    // (ceil(lpc / n_min) per cell vertically), and a point nearer to the grid's edge than its
    // half-length would lose weight to a node outside the grid
    solid.halfLength = 0.5 * h / spc;
    liquid.halfLength = 0.5 * h / std::max(lpc, freeWaterPointsPerCell(config));

    auto hydrostatic = [&](Real z) { return std::max(Real(0), rhoL * g * (zWater - z)); };

    // Per layer, what rests on its top: the buoyant weight of the layers above (K0 procedure) and
    // the excess pore pressure of an initial upward seepage at q0 through them (the head the
    // layers above take, Darcy-Forchheimer at n0). The seepage force lifts the effective stress
    // off the skeleton; at q0 = U_mf it carries the whole buoyant weight.
    const Real q0 = config.initial.filterVelocity, mu = config.liquid.viscosity;
    const DragLaw drag{mu, rhoL};
    auto seepageGradient = [&](const MaterialConfig& m) {  // i gamma_w, Pa/m
        const PermeabilityLaw law = PermeabilityLaw::from(m);
        return drag.gradient(law.kappa(m.porosity), law.ergunFactor(m.porosity), q0);
    };
    const std::size_t nl = config.layers.size();
    std::vector<Real> layerBottom(nl);
    Real z = config.filterLevel();
    for (std::size_t k = 0; k < nl; ++k) { layerBottom[k] = z; z += config.layers[k].thickness; }
    auto materialIndex = [&](const std::string& name) {
        for (std::size_t j = 0; j < materials.size(); ++j)
            if (materials[j].name == name) return static_cast<int>(j);
        return 0;
    };
    // What rests on layer k at a horizontal position: the buoyant weight of the layers above and
    // the head an initial seepage loses in them, each layer's material taken where the point is
    // (zones side by side are columns of their own)
    struct Above { Real overburden = 0, seepage = 0; };
    auto above = [&](std::size_t k, const Real* x) {
        Above a;
        for (std::size_t j = k + 1; j < nl; ++j) {
            const auto& m = config.material(config.layers[j].materialAt(x, D));
            const Real L = config.layers[j].thickness;
            a.overburden += (1 - m.porosity) * (m.grainDensity - rhoL) * g * L;
            a.seepage += seepageGradient(m) * L;
        }
        return a;
    };
    const bool fluidised = config.initial.state == InitialState::Fluidised;
    // The porosity where a point starts: n0 of its material, or n0 + sigma g(x) of a random field,
    // clipped to [n_min, n_max - 0.001] (the sand starts below its loosest state). The weight above
    // (the K0 stresses) is taken at n0: the gravity stage or the first steps settle the rest.
    const PorosityFieldConfig& field = config.initial.porosityField;
    const std::optional<RandomPorosityField> randomField =
        field.enabled ? std::optional<RandomPorosityField>(std::in_place, D, field.correlationLength, field.seed)
                      : std::nullopt;
    // A porosity wave (the stability problem, physics.md section 7) adds a sine; a suspension
    // (fluidised start) is not clipped, its porosity being above n_max anyway.
    const PorosityWaveConfig& wave = config.initial.porosityWave;
    auto porosityAt = [&](const MaterialConfig& mc, const Vec<D>& x) -> Real {
        Real n = mc.porosity;
        if (wave.enabled) {
            // across the column a cosine, symmetric about the smooth walls (planes of symmetry)
            const Real phase = 2 * kPi * (wave.lateral ? x[0] : x[D - 1] - config.filterLevel()) / wave.wavelength;
            n += wave.amplitude * (wave.lateral ? std::cos(phase) : std::sin(phase));
            if (fluidised) return n;
        }
        if (!randomField && !wave.enabled) return n;
        if (randomField) {
            Vec<D> at = x;
            if (field.mirror) at[0] = config.grid.width - x[0];  // the same bed seen from the other side
            n += field.standardDeviation * randomField->unitField(&at[0]);
        }
        return std::clamp(n, Real(mc.minPorosity), Real(mc.maxPorosity - 0.001));
    };
    Real chamberExcess = 0;  // excess pore pressure at the filter, shared by the chamber water

    for (std::size_t k = 0; k < nl; ++k) {
        const auto& layer = config.layers[k];
        const Real zb = layerBottom[k], zt = zb + layer.thickness;
        const Index cells = cellsIn(layer.thickness, h);
        // Excess pore pressure over hydrostatic at height zp: the seepage's head loss from the
        // sand top, or in a bed that starts fluidised (a suspension, no effective stress) its
        // whole buoyant weight.
        struct Local { const MaterialConfig* mc; int index; Real buoyant, excess; };
        auto local = [&](const Vec<D>& x) {
            const std::string& name = layer.materialAt(&x[0], D);
            const MaterialConfig& mc = config.material(name);
            const Above a = above(k, &x[0]);
            const Real zp = x[D - 1];
            const Real buoyant = a.overburden + (1 - mc.porosity) * (mc.grainDensity - rhoL) * g * (zt - zp);
            const Real excess = fluidised ? buoyant : a.seepage + seepageGradient(mc) * (zt - zp);
            return Local{&mc, materialIndex(name), buoyant, excess};
        };
        if (k == 0) {
            Vec<D> base{};
            base[D - 1] = zb;
            chamberExcess = local(base).excess;  // the material at x = 0 sets the chamber's
        }
        forEachLatticePoint(grid, spc, zb, zt, cells * spc, [&](const Vec<D>& x, Real V) {
            if (!made(x)) return;
            const Local at = local(x);
            const MaterialConfig& mc = *at.mc;
            Real stress[6] = {0, 0, 0, 0, 0, 0};
            if (config.initial.stress == InitialStress::K0) {
                const Real sv = -std::max(Real(0), at.buoyant - at.excess);
                stress[2] = sv;
                stress[0] = stress[1] = mc.k0 * sv;
            }
            if (config.initial.undrainedSurcharge) {
                // the water takes u0 = q m_v / (m_v + n/K_L) of the surcharge q
                const Real Eoed = materials[at.index].model->oedometricModulus();
                const Real mv = 1 / Eoed;
                const Real u0 = config.loads.surcharge * mv / (mv + mc.porosity / config.liquid.bulkModulus);
                const Real lateralRatio = mc.poissonRatio / (1 - mc.poissonRatio);
                const Real dsv = -(config.loads.surcharge - u0);
                stress[2] += dsv;
                stress[0] += lateralRatio * dsv;
                stress[1] += lateralRatio * dsv;
            }
            appendSolid(solid, x, V, porosityAt(mc, x), mc.grainDensity, at.index, stress,
                        fluidised ? kFluidisedState : kSolidState);
        });
        forEachLatticePoint(grid, lpc, zb, zt, cells * lpc, [&](const Vec<D>& x, Real V) {
            if (!made(x)) return;
            const Local at = local(x);
            const MaterialConfig& mc = *at.mc;
            const Real n = porosityAt(mc, x);
            Real u0 = 0;
            if (config.initial.undrainedSurcharge) {
                const Real mv = 1 / materials[at.index].model->oedometricModulus();
                u0 = config.loads.surcharge * mv / (mv + n / config.liquid.bulkModulus);
            }
            appendLiquid(liquid, x, V, n * rhoL * V, hydrostatic(x[D - 1]) + u0 + at.excess, q0 / n);
        });
    }

    // Free water: the chamber below the filter and the water above the sand. In an undrained
    // start the closed chamber shares the sand's excess pressure (it drains only upwards).
    if (config.initial.undrainedSurcharge) {
        const std::string& name = config.layers.front().material;  // no zones (CaseLoader)
        const auto& m = config.material(name);
        const Real mv = 1 / materials[materialIndex(name)].model->oedometricModulus();
        chamberExcess += config.loads.surcharge * mv / (mv + m.porosity / config.liquid.bulkModulus);
    }
    const int nzFree = freeWaterPointsPerCell(config);
    auto freeWater = [&](Real z0, Real z1, Real excess) {
        const Index nz = std::llround((z1 - z0) / h * nzFree);
        if (nz <= 0) return;
        forEachLatticePoint(grid, lpc, z0, z1, nz, [&](const Vec<D>& x, Real V) {
            if (!made(x)) return;
            appendLiquid(liquid, x, V, rhoL * V, hydrostatic(x[D - 1]) + excess, q0);
        });
    };
    freeWater(0.0, config.filterLevel(), chamberExcess);
    if (zWater > config.sandTop() + 1e-12) freeWater(config.sandTop(), zWater, 0.0);
}

template void buildColumn<1>(const CaseConfig&, const Grid<1>&, const std::vector<SolidMaterial>&,
                             SolidPoints<1>&, LiquidPoints<1>&, const std::function<bool(const Real*)>&);
template void buildColumn<2>(const CaseConfig&, const Grid<2>&, const std::vector<SolidMaterial>&,
                             SolidPoints<2>&, LiquidPoints<2>&, const std::function<bool(const Real*)>&);
template void buildColumn<3>(const CaseConfig&, const Grid<3>&, const std::vector<SolidMaterial>&,
                             SolidPoints<3>&, LiquidPoints<3>&, const std::function<bool(const Real*)>&);

}  // namespace qs
