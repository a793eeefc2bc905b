// sig-estimate: the a posteriori error estimate of a solved case, per triangle, for the adaptive
// loop (drivers/adapt.sh): Zienkiewicz and Zhu's recovery estimator in the norm of V that
// sig-error measures (post/recovery_estimate.hpp: formula and references),
//   eta_T = ||G eps(u_h) - eps(u_h)||_L2(T),   eta = (sum of eta_T^2)^(1/2).
//
//   sig-estimate DATAFILE [-o OUTDIR]
//
// Reads OUTDIR/case.nopo, case.mili and case.b (a static solve) or case.hist (a march: TIME card),
// checked to belong to the deck and to each other, as every stage does, and writes
//   OUTDIR/case.est                  DS EST: indicator (eta_T per triangle), estimate (eta),
//                                    dofs, estimator, norm, seconds (the indicators' time)
//   OUTDIR/<stem>_estimate.vtu       the indicators as the cell field error_indicator, with the
//                                    displacement (unless OUTPUT vtk=no)
// and prints the global estimate. A march is estimated for one mesh adapted to the whole march
// (drivers/adapt.sh says why): each kept state (step 0, every output_every-th step, the last) is
// estimated, the indicator of a triangle is its largest eta_T over them (the worst time of each
// place) and the estimate is eta at the last kept time, the time of sig-error's error; case.est
// adds times and estimates (eta per kept state) and estimate_max. A large-deformation law, a
// solve or march that did not converge and a 3D mesh are refused.
#include "post/stage_mains.hpp"

#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "material/mili.hpp"
#include "mesh/nopo.hpp"
#include "post/recovery_estimate.hpp"
#include "post/result_checks.hpp"
#include "post/vtk_writer.hpp"

#include <algorithm>
#include <iostream>

namespace sig {

int estimate_main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-estimate",
      .purpose = "The a posteriori error estimate of a solved case or march: Zienkiewicz-Zhu's "
                 "recovery estimator in the norm of V, eta_T = ||G eps(u_h) - eps(u_h)||_L2(T) "
                 "(G the nodal averaging of the strain per sub-domain), eta = (sum eta_T^2)^1/2, "
                 "in the units of sig-error's error. A march: eta at its last kept time, the "
                 "indicator of a triangle its largest eta_T over the kept states.",
      .reads = {"DATAFILE", "OUTDIR/case.nopo, case.mili (small-strain laws only)",
                "OUTDIR/case.b (sig-solve) or case.hist (sig-march)"},
      .writes = {"OUTDIR/case.est (indicator per triangle, estimate, dofs)",
                 "OUTDIR/<name>_estimate.vtu (cell field error_indicator; unless OUTPUT vtk=no)"},
      .cards = sig::stage_cards("estimate").cards};
  return sig::run_stage("sig-estimate", [&] {
    // 1. Command line and datafile: a static solve (case.b) or a march (case.hist).
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, help);
    const sig::Datafile& datafile = args.deck;
    const bool march = datafile.find("TIME") != nullptr;

    // 2. The mesh, small-strain laws only (the estimator measures the linearized strain, the
    //    norm of V: a large-deformation solution has another error norm), and the converged
    //    states: the solution, or the march's kept states with their times.
    const sig::Mesh mesh = sig::read_nopo(args.ds_path("nopo"));
    for (const sig::SubdomainMaterial& material : sig::read_mili(args.ds_path("mili")).entries)
      SIG_VERIFY(!material.hyperelastic, args.ds_path("mili").string()
                                             << ": sub-domain " << material.subdomain
                                             << " has a large-deformation law; sig-estimate "
                                                "estimates small-strain solutions only");
    const sig::Ds solution =
        march ? sig::read_ds(args.ds_path("hist"), "HIST") : sig::read_ds(args.ds_path("b"), "B");
    if (march)
      sig::verify_history_ds(solution, mesh);
    else
      sig::verify_solution_ds(solution, mesh);
    SIG_VERIFY(solution.integer("converged") != 0,
               solution.source << " holds a " << (march ? "march" : "solve")
                               << " that did not converge (Nv): no estimate of a solution that "
                                  "is not one");
    const std::vector<double> u_values = solution.reals("u");
    const std::vector<double> times =
        march ? solution.reals("output_time") : std::vector<double>{0.0};
    const auto ndof = static_cast<std::size_t>(2 * mesh.num_nodes());
    std::vector<Eigen::VectorXd> states;
    for (std::size_t n = 0; n < times.size(); ++n)
      states.push_back(Eigen::Map<const Eigen::VectorXd>(u_values.data() + n * ndof,
                                                         static_cast<Eigen::Index>(ndof)));

    // 3. The indicators and the global estimate.
    //    Timed (steady clock, the reading of the DS files left out, as sig-solve's phases are):
    //    the adaptive loop's cost is counted stage by stage (drivers/adapt.sh).
    const sig::Stopwatch clock;
    const sig::MarchIndicators e = sig::worst_time_indicators(mesh, states);
    const double seconds = clock.seconds();
    const double estimate = e.estimates.back();
    sig::Ds est("EST", datafile.title(), "sig-estimate");
    est.put("indicator", e.eta);
    est.put_scalar("estimate", estimate);
    est.put_int("dofs", static_cast<std::int64_t>(ndof));
    est.put_text("estimator", "zienkiewicz-zhu nodal averaging per sub-domain");
    est.put_text("norm", "||eps(u - u_h)||_L2");
    est.put_scalar("seconds", seconds);
    if (march) {
      est.put("times", times);
      est.put("estimates", e.estimates);
      est.put_scalar("estimate_max", *std::max_element(e.estimates.begin(), e.estimates.end()));
      est.put_text("indicator_rule", "largest eta_T over the kept states; estimate at the last");
    }
    sig::write_ds(args.ds_path("est"), est);

    // 4. The indicators for ParaView.
    const sig::Card* output = datafile.find("OUTPUT");
    if (output == nullptr || output->choice("vtk", {"yes", "no"}) == "yes") {
      const std::string stem =
          output ? output->file_name("name", datafile.stem()) : datafile.stem();
      const auto vtu = args.outdir / (stem + "_estimate.vtu");
      const Eigen::VectorXd& last = states.back();
      sig::write_vtu(vtu, mesh, {{"displacement", 2, {last.data(), last.data() + last.size()}}},
                     {{"error_indicator", 1, e.eta}},
                     {{"title", datafile.title()}, {"estimator", est.text("estimator")}},
                     {{"estimate", estimate}});
      std::cout << vtu.string() << "\n";
    }
    const auto worst = std::max_element(e.eta.begin(), e.eta.end()) - e.eta.begin();
    std::cout << "sig-estimate: eta = " << estimate << " (||eps(u - u_h)||_L2, Zienkiewicz-Zhu"
              << (march ? ", at t = " + std::to_string(times.back()) + " of " +
                              std::to_string(times.size()) + " kept states"
                        : std::string())
              << "), " << mesh.num_cells() << " triangles, " << 2 * mesh.num_nodes()
              << " dofs; largest eta_T" << (march ? " (over the kept states) = " : " = ")
              << e.eta[worst] << " on triangle " << worst + 1 << "; " << seconds << " s\n";
  });
}

} // namespace sig
