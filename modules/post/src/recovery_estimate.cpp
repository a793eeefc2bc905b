// The recovery estimator of post/recovery_estimate.hpp: nodal averaging per sub-domain, then the
// exact integral of the linear difference G eps_h - eps_h on each triangle.
#include "post/recovery_estimate.hpp"

#include "assembly/strain.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace sig {

namespace {

/// e : e for Voigt strains with engineering shear (e11, e22, 2 e12).
double strain_square(const Eigen::Vector3d& e) {
  return e[0] * e[0] + e[1] * e[1] + 0.5 * e[2] * e[2];
}

} // namespace

std::vector<std::array<Eigen::Vector3d, 3>> recovered_strains(const Mesh& mesh,
                                                              const Eigen::VectorXd& u) {
  const std::vector<Eigen::Vector3d> strains = element_strains(mesh, u);
  // Sums of area x strain and of area per (sub-domain, node): a node on a material interface
  // gets one recovered value per side.
  std::map<std::pair<int, int>, std::pair<Eigen::Vector3d, double>> sums;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const double area = 0.5 * std::abs(signed_double_area(mesh, t));
    for (int v : mesh.cells[t]) {
      auto [it, fresh] = sums.try_emplace({mesh.subdomain[t], v}, Eigen::Vector3d::Zero(), 0.0);
      it->second.first += area * strains[t];
      it->second.second += area;
    }
  }
  std::vector<std::array<Eigen::Vector3d, 3>> recovered(mesh.cells.size());
  for (int t = 0; t < mesh.num_cells(); ++t)
    for (int i = 0; i < 3; ++i) {
      const auto& [weighted, area] = sums.at({mesh.subdomain[t], mesh.cells[t][i]});
      recovered[t][i] = weighted / area;
    }
  return recovered;
}

double linear_strain_square_integral(double area, const std::array<Eigen::Vector3d, 3>& g) {
  // integral of phi_i phi_j = area (1 + delta_ij) / 12.
  return area / 12 *
         (strain_square(g[0]) + strain_square(g[1]) + strain_square(g[2]) +
          strain_square(g[0] + g[1] + g[2]));
}

ErrorIndicators recovery_indicators(const Mesh& mesh, const Eigen::VectorXd& u) {
  SIG_VERIFY(mesh.dim == 2, "sig-estimate: the error estimate of a 3D mesh is not implemented yet "
                            "(issue 29; 2D only)");
  SIG_VERIFY(mesh.num_cells() > 0, "recovery_indicators: the mesh has no triangle");
  const std::vector<Eigen::Vector3d> strains = element_strains(mesh, u);
  const auto recovered = recovered_strains(mesh, u);
  ErrorIndicators out;
  out.eta.resize(mesh.cells.size());
  double sum = 0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    std::array<Eigen::Vector3d, 3> difference;
    for (int i = 0; i < 3; ++i)
      difference[i] = recovered[t][i] - strains[t];
    const double square =
        linear_strain_square_integral(0.5 * std::abs(signed_double_area(mesh, t)), difference);
    out.eta[t] = std::sqrt(square);
    sum += square;
  }
  out.estimate = std::sqrt(sum);
  return out;
}

MarchIndicators worst_time_indicators(const Mesh& mesh,
                                      const std::vector<Eigen::VectorXd>& states) {
  SIG_VERIFY(!states.empty(), "worst_time_indicators: the march kept no state");
  MarchIndicators out;
  out.eta.assign(mesh.cells.size(), 0.0);
  for (const Eigen::VectorXd& u : states) {
    const ErrorIndicators e = recovery_indicators(mesh, u);
    out.estimates.push_back(e.estimate);
    for (std::size_t t = 0; t < e.eta.size(); ++t)
      out.eta[t] = std::max(out.eta[t], e.eta[t]);
  }
  return out;
}

} // namespace sig
