#include "contact/contact_elements.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/ranges.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace sig {

namespace {

/// The CONT array of a law parameter's card field.
std::string cont_array_of(const std::string& field) {
  if (field == "g") return "depth";
  if (field == "bound" || field == "a" || field == "b" || field == "alpha")
    return "friction_" + field;
  return field;
}

} // namespace

void write_cont(const std::filesystem::path& path, const ContactElements& elements,
                const std::string& title, const std::string& creator) {
  const int m = elements.size();
  SIG_VERIFY(static_cast<int>(elements.lagrange_node.size()) == m &&
                 static_cast<int>(elements.normal.size()) == m &&
                 static_cast<int>(elements.tangent.size()) == m && elements.gap.size() == m &&
                 elements.weight.size() == m && static_cast<int>(elements.law.size()) == m,
             "write_cont " << path.string() << ": arrays of different lengths");
  std::vector<std::int64_t> node(m), lagrange(m), law(m), friction_law(m), friction_bound(m),
      friction_of(m);
  const int d = elements.dim;
  SIG_VERIFY(elements.obstacle.point.size() == d && elements.obstacle.normal.size() == d,
             "write_cont " << path.string() << ": an obstacle of another dimension than " << d);
  std::vector<double> normal(d * m), tangent(d * m), cn(m), c3(m), depth(m), mu(m), threshold(m),
      a(m), b(m), alpha(m);
  for (int i = 0; i < m; ++i) { // files are 1-based
    node[i] = elements.node[i] + 1;
    lagrange[i] = elements.lagrange_node[i] + 1;
    SIG_VERIFY(elements.normal[i].size() == d && elements.tangent[i].size() == d,
               "write_cont " << path.string() << ": element " << i + 1 << " is not " << d << "D");
    for (int c = 0; c < d; ++c) {
      normal[d * i + c] = elements.normal[i][c];
      tangent[d * i + c] = elements.tangent[i][c];
    }
    const ContactLaw& l = elements.law[i];
    law[i] = static_cast<std::int64_t>(l.normal);
    cn[i] = l.cn;
    c3[i] = std::isfinite(l.c3) ? l.c3 : 0.0; // 0: no truncation
    depth[i] = l.depth;
    friction_law[i] = static_cast<std::int64_t>(l.friction);
    mu[i] = l.mu;
    threshold[i] = l.threshold;
    friction_bound[i] = static_cast<std::int64_t>(l.bound);
    a[i] = l.a;
    b[i] = l.b;
    alpha[i] = l.alpha;
    friction_of[i] = static_cast<std::int64_t>(l.of);
  }
  Ds ds("CONT", title, creator);
  ds.put_int("num_nodes", elements.num_nodes);
  ds.put_int("ref", elements.ref);
  ds.put_scalar("thickness", elements.thickness);
  ds.put("node", node);
  ds.put("lagrange_node", lagrange);
  ds.put("normal", normal, {m, d});
  ds.put("tangent", tangent, {m, d});
  ds.put("gap", std::span<const double>(elements.gap.data(), m));
  ds.put("weight", std::span<const double>(elements.weight.data(), m));
  ds.put("law", law);
  ds.put("cn", cn);
  ds.put("c3", c3);
  ds.put("depth", depth);
  ds.put("friction_law", friction_law);
  ds.put("mu", mu);
  ds.put("threshold", threshold);
  ds.put("friction_bound", friction_bound);
  ds.put("friction_a", a);
  ds.put("friction_b", b);
  ds.put("friction_alpha", alpha);
  ds.put("friction_of", friction_of);
  ds.put_text("obstacle_kind", elements.obstacle.kind);
  ds.put("obstacle_point", std::span<const double>(elements.obstacle.point.data(), d));
  ds.put("obstacle_normal", std::span<const double>(elements.obstacle.normal.data(), d));
  ds.put_scalar("obstacle_radius", elements.obstacle.radius);
  write_ds(path, ds);
}

ContactElements read_cont(const std::filesystem::path& path, const Mesh& mesh) {
  const Ds ds = read_ds(path, "CONT");
  const std::string where = "CONT file " + path.string();
  ContactElements elements;
  // Checked before they are narrowed: 1e15 would otherwise read as -1530494976.
  const std::int64_t num_nodes = ds.integer("num_nodes"), ref = ds.integer("ref");
  SIG_VERIFY(num_nodes >= 1 && num_nodes <= max_mesh_nodes,
             where << ": array 'num_nodes': " << num_nodes << " is not in 1.." << max_mesh_nodes
                   << " (the nodes a mesh may have)");
  SIG_VERIFY(ref >= 1 && ref <= std::numeric_limits<int>::max(),
             where << ": array 'ref': " << ref << " is not a reference (1.."
                   << std::numeric_limits<int>::max() << ")");
  SIG_VERIFY(num_nodes == mesh.num_nodes(), where << ": array 'num_nodes': " << num_nodes
                                                  << ", the mesh has " << mesh.num_nodes());
  elements.num_nodes = static_cast<int>(num_nodes);
  const int d = mesh.dim;
  elements.dim = d;
  elements.ref = static_cast<int>(ref);
  elements.thickness = ds.scalar("thickness");
  verify_in_range(elements.thickness, "MATERIAL", "thickness", where, "thickness", 1);
  // The geometry's meaning (core/ranges.hpp): an edited gap of 1e300 held the body off.
  const ValueRange gap_bound = gap_range();
  const ValueRange weight_bound = weight_range(elements.thickness, diameter(mesh), d);
  const std::vector<std::int64_t> node = ds.ints("node");
  const std::vector<std::int64_t> lagrange = ds.ints("lagrange_node");
  const std::vector<std::int64_t> law = ds.ints("law");
  const std::vector<std::int64_t> friction_law = ds.ints("friction_law");
  const std::vector<double> normal = ds.reals("normal");
  const std::vector<double> tangent = ds.reals("tangent");
  const std::vector<double> gap = ds.reals("gap");
  const std::vector<double> weight = ds.reals("weight");
  const std::vector<double> cn = ds.reals("cn");
  const std::vector<double> c3 = ds.reals("c3");
  const std::vector<double> depth = ds.reals("depth");
  const std::vector<double> mu = ds.reals("mu");
  const std::vector<double> threshold = ds.reals("threshold");
  const std::vector<std::int64_t> friction_bound = ds.ints("friction_bound");
  const std::vector<double> a = ds.reals("friction_a");
  const std::vector<double> b = ds.reals("friction_b");
  const std::vector<double> alpha = ds.reals("friction_alpha");
  const std::vector<std::int64_t> friction_of = ds.ints("friction_of");
  const std::size_t m = node.size();
  const std::initializer_list<std::size_t> per_element = {
      lagrange.size(),   law.size(),       friction_law.size(), gap.size(),
      weight.size(),     cn.size(),        c3.size(),           depth.size(),
      mu.size(),         threshold.size(), normal.size() / d,   tangent.size() / d,
      a.size(),          b.size(),         alpha.size(),        friction_bound.size(),
      friction_of.size()};
  SIG_VERIFY(normal.size() % d == 0 && tangent.size() % d == 0 &&
                 std::all_of(per_element.begin(), per_element.end(),
                             [m](std::size_t size) { return size == m; }),
             where << ": arrays node, lagrange_node, normal, tangent, gap, weight and the law "
                      "arrays disagree in length");
  for (std::size_t i = 0; i < m; ++i) {
    SIG_VERIFY(node[i] >= 1 && node[i] <= elements.num_nodes,
               where << ": array node, element " << i + 1 << ": node " << node[i]
                     << " is not in 1.." << elements.num_nodes);
    // Lagrange nodes are numbered after the mesh nodes, in element order (Remark 3.1).
    SIG_VERIFY(lagrange[i] == elements.num_nodes + static_cast<std::int64_t>(i) + 1,
               where << ": array lagrange_node, element " << i + 1 << ": " << lagrange[i]
                     << " should be " << elements.num_nodes + i + 1);
    const Point n = Eigen::Map<const Eigen::VectorXd>(normal.data() + d * i, d);
    SIG_VERIFY(std::abs(n.norm() - 1) <= 1e-12,
               where << ": array normal, element " << i + 1 << " is not a unit vector");
    const Point t = Eigen::Map<const Eigen::VectorXd>(tangent.data() + d * i, d);
    SIG_VERIFY((t - contact_frame(n).col(0)).norm() <= 1e-12,
               where << ": array tangent, element " << i + 1
                     << (d == 2 ? " is not (n2, -n1)" : " is not the first tangent of its normal"));
    verify_in_range(gap[i], gap_bound, where, "gap", i + 1);
    verify_in_range(weight[i], weight_bound, where, "weight", i + 1);
    ContactLaw l;
    try {
      l.normal = normal_law_of_id(law[i]);
      l.friction = friction_law_of_id(friction_law[i]);
      l.bound = friction_bound_of_id(friction_bound[i]);
      l.of = slip_measure_of_id(friction_of[i]);
    } catch (const Error& e) {
      SIG_VERIFY(false, where << ": arrays law / friction_law / friction_bound / friction_of, "
                              << "element " << i + 1 << ": " << e.what());
    }
    l.cn = cn[i];
    l.c3 = c3[i] == 0 ? l.c3 : c3[i];
    l.depth = depth[i];
    l.mu = mu[i];
    l.threshold = threshold[i];
    l.a = a[i];
    l.b = b[i];
    l.alpha = alpha[i];
    if (const std::optional<LawProblem> problem = law_problem(l))
      SIG_VERIFY(false, where << ": array " << cont_array_of(problem->field) << ", element "
                              << i + 1 << ": " << problem->what);
    elements.law.push_back(l);
    elements.tangent.push_back(t);
    elements.node.push_back(static_cast<int>(node[i] - 1));
    elements.lagrange_node.push_back(static_cast<int>(lagrange[i] - 1));
    elements.normal.push_back(n);
  }
  elements.gap = Eigen::Map<const Eigen::VectorXd>(gap.data(), static_cast<Eigen::Index>(m));
  elements.weight = Eigen::Map<const Eigen::VectorXd>(weight.data(), static_cast<Eigen::Index>(m));

  elements.obstacle.kind = ds.text("obstacle_kind");
  const std::vector<double> point = ds.reals("obstacle_point");
  const std::vector<double> obstacle_normal = ds.reals("obstacle_normal");
  SIG_VERIFY(static_cast<int>(point.size()) == d && static_cast<int>(obstacle_normal.size()) == d,
             where << ": arrays obstacle_point and obstacle_normal must hold " << d
                   << " values (the mesh is " << d << "D)");
  elements.obstacle.point = Eigen::Map<const Eigen::VectorXd>(point.data(), d);
  elements.obstacle.normal = Eigen::Map<const Eigen::VectorXd>(obstacle_normal.data(), d);
  elements.obstacle.radius = ds.scalar("obstacle_radius");
  try {
    make_obstacle(elements.obstacle); // the description must rebuild a valid obstacle
  } catch (const Error& e) {
    SIG_VERIFY(false, where << ": " << e.what());
  }
  return elements;
}

} // namespace sig
