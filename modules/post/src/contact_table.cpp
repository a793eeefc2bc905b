#include "post/contact_table.hpp"

#include "core/error.hpp"
#include "ds_values.hpp"

#include <cmath>
#include <cstdio>

namespace sig {

std::vector<ContactRow> contact_rows(const Mesh& mesh, const Ds& cont, const Ds& solution) {
  const auto node = numbers(cont, "node");
  const auto normal = numbers(cont, "normal");
  const auto tangent = numbers(cont, "tangent");
  const auto gap = numbers(cont, "gap");
  const auto weight = numbers(cont, "weight");
  const auto u = solution.reals("u");
  const auto multiplier = numbers(solution, "multiplier");
  const auto tangential = numbers(solution, "tangential_multiplier");
  const auto normal_status = numbers(solution, "normal_status");
  const auto friction_status = numbers(solution, "friction_status");
  const std::size_t m = node.size();
  const std::size_t d = static_cast<std::size_t>(mesh.dim);
  SIG_VERIFY(normal.size() == d * m && tangent.size() == d * m && gap.size() == m &&
                 weight.size() == m,
             cont.source << ": arrays node, normal, tangent (m x " << d
                         << "), gap, weight disagree for m = " << m);
  // In 3D with friction, two tangential components per element, along t1 and t2 = n x t1 (the
  // contact frame, contact_law.hpp).
  const bool pair = d == 3 && m > 0 && tangential.size() == 2 * m;
  SIG_VERIFY(multiplier.size() == m && (tangential.size() == m || pair) &&
                 normal_status.size() == m && friction_status.size() == m,
             solution.source << ": arrays multiplier, tangential_multiplier, normal_status and "
                                "friction_status hold "
                             << multiplier.size() << ", " << tangential.size() << ", "
                             << normal_status.size() << " and " << friction_status.size()
                             << " values for " << m << " contact elements");
  SIG_VERIFY(u.size() == d * mesh.nodes.size(), solution.source << ": array 'u' holds " << u.size()
                                                                << " values for "
                                                                << mesh.num_nodes() << " nodes");
  std::vector<ContactRow> rows(m);
  for (std::size_t i = 0; i < m; ++i) {
    // Checked before it is narrowed: 2^32 + 2 would otherwise read as node 2.
    SIG_VERIFY(node[i] >= 1 && node[i] <= mesh.num_nodes(),
               cont.source << ": array 'node' holds " << node[i] << " at element " << i + 1
                           << ", outside 1.." << mesh.num_nodes());
    const int k = static_cast<int>(node[i]) - 1;
    auto& r = rows[i];
    r.node = k + 1;
    r.dim = mesh.dim;
    double un = 0, slip = 0;
    for (std::size_t c = 0; c < d; ++c) {
      const double x = mesh.nodes[k][static_cast<Eigen::Index>(c)], uc = u[d * k + c];
      (c == 0 ? r.x1 : c == 1 ? r.x2 : r.x3) = x;
      (c == 0 ? r.u1 : c == 1 ? r.u2 : r.u3) = uc;
      // u_n = -n . u with n the obstacle's outward normal (contact/contact_elements.hpp); the
      // slip along the (first) tangent.
      un -= uc * normal[d * i + c];
      slip += uc * tangent[d * i + c];
    }
    r.gap = gap[i] - un;
    r.multiplier = multiplier[i];
    r.weight = weight[i];
    SIG_VERIFY(weight[i] > 0,
               cont.source << ": array 'weight' holds " << weight[i] << " at element " << i + 1);
    r.pressure = multiplier[i] / weight[i];
    const double T1 = tangential[pair ? 2 * i : i], T2 = pair ? tangential[2 * i + 1] : 0.0;
    r.tangential_multiplier = T1;
    r.tangential_pressure = T1 / weight[i];
    r.slip = slip;
    if (d == 3) { // magnitudes, and the vectors in global axes
      double slip_squared = 0;
      const double* n = &normal[3 * i];
      const double* t1 = &tangent[3 * i];
      const double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2],
                            n[0] * t1[1] - n[1] * t1[0]};
      for (std::size_t c = 0; c < 3; ++c) {
        const double uc = c == 0 ? r.u1 : c == 1 ? r.u2 : r.u3;
        r.slip_vector[c] = uc + un * normal[3 * i + c]; // u - (n . u) n, n . u = -u_n
        slip_squared += r.slip_vector[c] * r.slip_vector[c];
        r.tangential_force[c] = T1 * t1[c] + T2 * t2[c];
      }
      r.slip = std::sqrt(slip_squared);
      r.tangential_multiplier = std::hypot(T1, T2);
      r.tangential_pressure = std::hypot(T1, T2) / weight[i];
    }
    try {
      r.normal_status = normal_status_of_code(static_cast<long>(normal_status[i]));
      r.friction_status = friction_status_of_code(static_cast<long>(friction_status[i]));
    } catch (const Error& e) {
      SIG_VERIFY(false, solution.source << ": element " << i + 1 << ": " << e.what());
    }
    r.contact =
        r.normal_status == NormalStatus::compliance || r.normal_status == NormalStatus::unilateral;
  }
  return rows;
}

std::string contact_csv(const std::vector<ContactRow>& rows, bool converged) {
  const bool three = !rows.empty() && rows.front().dim == 3;
  std::string out = three ? "node,x1,x2,x3,u1,u2,u3," : "node,x1,x2,u1,u2,";
  out += "gap,multiplier,pressure,status,normal_status,friction_status,tangential_multiplier,"
         "tangential_pressure,slip,";
  out += three ? "slip_1,slip_2,slip_3,tangential_force_1,tangential_force_2,tangential_force_3,"
                 "converged\n"
               : "converged\n";
  char line[768];
  for (const auto& r : rows) {
    const char* status = r.contact                               ? "contact"
                         : r.normal_status == NormalStatus::held ? "held"
                                                                 : "free";
    if (three)
      std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,", r.node, r.x1,
                    r.x2, r.x3, r.u1, r.u2, r.u3);
    else
      std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g,%.17g,", r.node, r.x1, r.x2, r.u1,
                    r.u2);
    out += line;
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%s,%s,%s,%.17g,%.17g,%.17g,", r.gap,
                  r.multiplier, r.pressure, status, label(r.normal_status).c_str(),
                  label(r.friction_status).c_str(), r.tangential_multiplier, r.tangential_pressure,
                  r.slip);
    out += line;
    if (three) {
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,", r.slip_vector[0],
                    r.slip_vector[1], r.slip_vector[2], r.tangential_force[0],
                    r.tangential_force[1], r.tangential_force[2]);
      out += line;
    }
    out += converged ? "1\n" : "0\n";
  }
  return out;
}

std::vector<PressureSample> pressure_samples(const std::vector<ContactRow>& rows,
                                             double centre_x1) {
  std::vector<PressureSample> samples;
  samples.reserve(rows.size());
  for (const auto& r : rows)
    samples.push_back({r.x1 - centre_x1, r.pressure, r.weight, r.contact});
  return samples;
}

} // namespace sig
