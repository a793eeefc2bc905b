// sig-error: the error of a solved case against a reference case on a finer mesh, in the norm of
// V (post/error_norm.hpp): ||u_ref - P u_h||_V = ||eps(u_ref - P u_h)||_L2, exact on nested
// meshes (the convergence figures 4.7, 5.12, 6.5) and an interpolation otherwise.
//
//   sig-error [--json] [--window X0,X1,Y0,Y1] CASE_DIR REFERENCE_DIR
//
// Each folder holds a chain's output: case.nopo and case.b (a static solve), or case.nopo and
// case.hist (a march in time: the error at every output time of the case that the reference
// also kept, its value at the last one and its maximum, ALGORITHMS.md 0.6). --window restricts
// both norms to the reference triangles whose centroid lies in the rectangle: the error of a
// sub-domain away from singular corners (scene 5's Fig 5.12). Two meshes of different domains
// are refused (post/same_domain.hpp: their boundaries within 2 % of the reference's size).
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/json.hpp"
#include "core/stage.hpp"
#include "mesh/nopo.hpp"
#include "post/error_norm.hpp"
#include "post/same_domain.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// The displacement states of a case folder with their times (one state, time 0, for case.b).
struct States {
  sig::Mesh mesh;
  std::vector<double> time;
  std::vector<Eigen::VectorXd> u;
};

States read_states(const std::filesystem::path& dir) {
  States s;
  s.mesh = sig::read_nopo(dir / "case.nopo");
  sig::require_2d(s.mesh, "sig-error", "error norm");
  const auto ndof = static_cast<std::size_t>(2 * s.mesh.num_nodes());
  const auto b = dir / "case.b", hist = dir / "case.hist";
  const bool static_case = std::filesystem::exists(b);
  SIG_VERIFY(static_case || std::filesystem::exists(hist),
             dir.string() << ": neither case.b nor case.hist (run the case's chain first)");
  const sig::Ds ds = static_case ? sig::read_ds(b, "B") : sig::read_ds(hist, "HIST");
  const std::vector<double> u = ds.reals("u");
  const std::vector<double> times =
      static_case ? std::vector<double>{0.0} : ds.reals("output_time");
  SIG_VERIFY(u.size() == times.size() * ndof, ds.source << ": array 'u' holds " << u.size()
                                                        << " values, not " << times.size()
                                                        << " states of " << ndof << " dofs ("
                                                        << s.mesh.num_nodes() << " mesh nodes)");
  s.time = times;
  for (std::size_t k = 0; k < times.size(); ++k)
    s.u.push_back(
        Eigen::Map<const Eigen::VectorXd>(u.data() + k * ndof, static_cast<Eigen::Index>(ndof)));
  return s;
}

/// "X0,X1,Y0,Y1" with X0 < X1, Y0 < Y1.
sig::Window parse_window(const std::string& text) {
  std::vector<double> v;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    SIG_VERIFY(used > 0 && used == item.size() && std::isfinite(x),
               "--window " << text << ": '" << item << "' is not a number");
    v.push_back(x);
  }
  // getline drops an empty last field: "1,2,3,4," would pass as four numbers.
  SIG_VERIFY(v.size() == 4 && text.back() != ',' && v[0] < v[1] && v[2] < v[3],
             "--window " << text << ": expected X0,X1,Y0,Y1 with X0 < X1 and Y0 < Y1");
  return {v[0], v[1], v[2], v[3]};
}

} // namespace

int main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-error",
      .purpose = "The error of a solved case against a reference case on a finer mesh in the "
                 "norm of V, ||eps(u_ref - P u_h)||_L2 on the reference mesh (P the P1 "
                 "interpolation of the case's field at the reference nodes: exact on nested "
                 "meshes); for marches in time at every shared output time. The two meshes "
                 "must discretize one domain: every boundary node of each lies within 2 % of "
                 "the reference's size (its bounding box's diagonal) of the other's boundary.",
      .reads = {"CASE_DIR/case.nopo, case.b or case.hist", "REFERENCE_DIR/the same"},
      .writes = {"standard output"},
      .cards = {},
      .usage = "[--json] [--window X0,X1,Y0,Y1] CASE_DIR REFERENCE_DIR",
      .options = {{"--json", "stable keys for scripts: error, reference_norm, relative, "
                             "max_error, times, errors (and window)"},
                  {"--window X0,X1,Y0,Y1", "the norms on the reference triangles whose centroid "
                                           "lies in [X0, X1] x [Y0, Y1] only"}}};
  return sig::run_stage("sig-error", [&] {
    sig::handle_help_and_version(argc, argv, help);
    bool json = false;
    std::optional<sig::Window> window;
    std::vector<std::filesystem::path> dirs;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--json")
        json = true;
      else if (a == "--window") {
        SIG_VERIFY(i + 1 < argc, "--window needs X0,X1,Y0,Y1");
        window = parse_window(argv[++i]);
      } else if (!a.empty() && a[0] == '-')
        SIG_VERIFY(false, "unknown option " << a << "; usage: sig-error " << help.usage);
      else
        dirs.emplace_back(a);
    }
    SIG_VERIFY(dirs.size() == 2, "usage: sig-error " << help.usage);
    const States coarse = read_states(dirs[0]), reference = read_states(dirs[1]);
    const std::string mismatch =
        sig::domain_mismatch(coarse.mesh, (dirs[0] / "case.nopo").string(), reference.mesh,
                             (dirs[1] / "case.nopo").string());
    SIG_VERIFY(mismatch.empty(), mismatch);

    // The case's output times that the reference kept too.
    std::vector<double> times, errors;
    double last_reference_norm = 0;
    const double scale = std::max(1.0, std::abs(coarse.time.back()));
    for (std::size_t k = 0; k < coarse.time.size(); ++k)
      for (std::size_t j = 0; j < reference.time.size(); ++j)
        if (std::abs(coarse.time[k] - reference.time[j]) <= 1e-9 * scale) {
          const sig::StrainError e =
              sig::strain_error(reference.mesh, reference.u[j], coarse.mesh, coarse.u[k], window);
          times.push_back(coarse.time[k]);
          errors.push_back(e.error);
          last_reference_norm = e.reference_norm;
          break;
        }
    SIG_VERIFY(!errors.empty(), dirs[0].string()
                                    << " and " << dirs[1].string() << " share no output time");
    double max_error = 0;
    for (double e : errors)
      max_error = std::max(max_error, e);
    const double error = errors.back();
    const double relative = last_reference_norm > 0 ? error / last_reference_norm : error;
    if (json) {
      sig::Json out = sig::Json::object();
      out.set("norm", std::string("||eps(u_ref - P u_h)||_L2"));
      out.set("error", error);
      out.set("reference_norm", last_reference_norm);
      out.set("relative", relative);
      out.set("max_error", max_error);
      out.set("times", sig::Json::array_of(times));
      out.set("errors", sig::Json::array_of(errors));
      if (window)
        out.set("window", sig::Json::array_of(
                              std::vector<double>{window->x0, window->x1, window->y0, window->y1}));
      std::cout << out.dump() << "\n";
    } else {
      std::cout << "sig-error: ||eps(u_ref - P u_h)||_L2 = " << error << " (relative " << relative
                << ", reference norm " << last_reference_norm << ")";
      if (times.size() > 1)
        std::cout << " at t = " << times.back() << "; maximum over " << times.size() << " times "
                  << max_error;
      std::cout << "\n";
    }
  });
}
