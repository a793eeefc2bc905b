#pragma once
// Post-processing of a displacement: P1 strains and stresses are constant on each triangle.
// Vectors are Voigt with engineering shear, eps = (e11, e22, 2 e12), sigma = (s11, s22, s12).
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace sig {

struct Mesh;
struct MaterialTable;

/// eps = B u_e on every triangle; u has 2 * nodes values (dof = 2 node + component).
std::vector<Eigen::Vector3d> element_strains(const Mesh& mesh, const Eigen::VectorXd& u);

/// ||eps(u)||_L2(Omega) = (integral of eps(u) : eps(u))^(1/2), the norm of V (thesis (2.6),
/// (u, v)_V = integral of eps(u) . eps(v), l.3041; ALGORITHMS.md 0.6): exact for P1, whose
/// strain is constant on each cell; a mesh of either dimension (u: dim values per node).
double strain_norm(const Mesh& mesh, const Eigen::VectorXd& u);

/// The same integral over the cells t with counts(t) only (an error away from singular
/// corners: sig-error --window).
double strain_norm(const Mesh& mesh, const Eigen::VectorXd& u,
                   const std::function<bool(int)>& counts);

/// sigma = D eps with the law of each triangle's sub-domain.
std::vector<Eigen::Vector3d> element_stresses(const Mesh& mesh, const MaterialTable& table,
                                              const Eigen::VectorXd& u);

} // namespace sig
