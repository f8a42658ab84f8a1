#include "physics/WaveSpeeds.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace qs {

MixtureWaves mixtureWaves(Real Eoed, Real KL, Real n, Real rhoS, Real rhoL) {
    Eigen::Matrix2d K, M;
    K << Eoed + (1 - n) * (1 - n) * KL / n, (1 - n) * KL,
         (1 - n) * KL, n * KL;
    M << (1 - n) * rhoS, 0,
         0, n * rhoL;
    // K and M symmetric, M positive definite: the eigenvalues c^2 come out in increasing order
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> waves(K, M, Eigen::EigenvaluesOnly);
    MixtureWaves w;
    w.slow = std::sqrt(std::max(waves.eigenvalues()(0), 0.0));
    w.fast = std::sqrt(std::max(waves.eigenvalues()(1), 0.0));
    w.skeleton = std::sqrt(Eoed / ((1 - n) * rhoS));
    return w;
}

Real freeWaterWave(Real KL, Real rhoL) { return std::sqrt(KL / rhoL); }

}  // namespace qs
