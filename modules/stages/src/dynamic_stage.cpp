#include "stages/dynamic_stage.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/initial.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "contact/contact_law.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "integrator/backward_euler_scheme.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nopo.hpp"
#include "solver/mpi_session.hpp"
#include "solver/solver_card.hpp"
#include "stages/convexification_step.hpp"
#include "stages/march_inputs.hpp"
#include "stages/march_stage.hpp"
#include "stages/march_tables.hpp"
#include "stages/rank_rows.hpp"

#include <cstdio>
#include <iostream>
#include <optional>

namespace sig {

namespace {

// The cards a backward-Euler deck must not have, each refused on its line and field.
void refuse_other_models(const Datafile& datafile, const TimeParameters& time) {
  const Card& time_card = datafile.require("TIME");
  if (time.mass == MassChoice::emm)
    time_card.fail("mass", "mass=emm belongs to the midpoint strategies' Signorini contact; the "
                           "backward-Euler march takes mass=consistent or lumped");
  if (const Card* contact = datafile.find("CONTACT")) {
    for (const char* dynamic : {"strategy", "r"})
      if (contact->has(dynamic))
        contact->fail(dynamic, "is a field of the midpoint strategies; the backward-Euler march "
                               "takes its contact law from law= and its method from SOLVER");
    const std::string law = contact->choice("law", normal_law_choices);
    if (ContactLaw{normal_law_named(law)}.in_velocity())
      contact->fail("law", "law=" + law +
                               " is a law of the velocity (the quasistatic march of ch. 5); the "
                               "dynamic march takes a law of the displacement: compliance, "
                               "compliance-unilateral, signorini");
  }
  if (const Card* friction = datafile.find("FRICTION"))
    if (friction->choice("law", friction_law_choices) == "nonmonotone" &&
        friction->choice("of", slip_measure_choices) != "slip-rate")
      friction->fail("of", "the backward-Euler march's tangential variable is the slip rate "
                           "w_t: give of=slip-rate (ch. 6, (6.6))");
  for (const Card* memory : datafile.all("MEMORY"))
    memory->fail("", "a memory term belongs to the quasistatic march of ch. 5 (TIME "
                     "scheme=quasistatic); the dynamic march of ch. 6 has none");
}

} // namespace

void run_backward_euler_march(const StageArgs& args, const Datafile& datafile,
                              const TimeParameters& time) {
  // 1. Cards: what the march does not model, then SOLVER and CONVEXIFICATION.
  refuse_other_models(datafile, time);
  SolverCard solver = read_solver_card(datafile, /*march=*/true);
  if (mpi::launched()) require_mumps_under_mpirun(datafile, solver.backend);
  if (datafile.find("CONTACT") != nullptr)
    verify_total_iterations(datafile, ContactSolverParameters::solve_max_iterations, time.steps);

  // 2. Mesh, laws, the assembled system (K, M, V, loads in time; under mpirun this rank's rows of
  //    the matrices, stages/rank_rows.hpp), the initial state.
  const Mesh mesh = read_nopo(args.ds_path("nopo"));
  for (const SubdomainMaterial& m : read_mili(args.ds_path("mili")).entries)
    if (m.hyperelastic)
      datafile.all("MATERIAL")
          .front()
          ->fail("law", "a hyperelastic law is large deformation; the backward-Euler march is "
                        "small strain (law=hooke or kelvin-voigt)");
  const LinearSystem system = read_tae_of_rank(args.ds_path("tae"), mesh, /*march=*/true);
  if (system.M.nonZeros() == 0) {
    const std::string why = "every MATERIAL has density 0: the dynamic march needs a mass, give "
                            "the MATERIAL cards rho > 0 (1e-6 GPa s^2/m^2 is 1000 kg/m^3 in GPa "
                            "units)";
    const auto materials = datafile.all("MATERIAL");
    if (!materials.empty()) materials.front()->fail("rho", why);
    throw InputError(datafile.path, 0, "rho", why);
  }
  const ReducedSystem reduced = reduce_on_ranks(system);
  const InitialFields initial = initial_fields(datafile, mesh);
  Eigen::VectorXd u0 = reduced.restrict(initial.u), w0 = reduced.restrict(initial.v);

  // 3. The contact boundary, its laws turned into laws of the velocity; the step matrix
  //    factorized and condensed once by the march.
  std::optional<ContactElements> elements;
  std::optional<VelocityContact> contact;
  Eigen::VectorXd gap;
  if (datafile.find("CONTACT") != nullptr) {
    elements = read_cont(args.ds_path("cont"), mesh);
    contact = velocity_contact(*elements, reduced);
    gap = elements->gap;
  }
  DynamicBackwardEuler scheme(
      viscoelastic_problem(system, reduced, mass_matrix(system, time.mass, mesh)), time.k,
      std::move(u0), std::move(w0), gap, contact ? contact->setting : ContactSetting{});
  if (contact) contact->setting = scheme.velocity_setting();
  solver.parameters = scheme.velocity_parameters(solver.parameters);

  // 4. The step solver: the one Newton driver, or the convexification loop around it.
  ConvexificationRecords convexification;
  const StepSolver step_solver =
      convexification_step(scheme, contact ? &*contact : nullptr, solver, convexification);
  LinearContactMarch march(scheme, contact ? &*contact : nullptr, solver.parameters, solver.backend,
                           step_solver);

  // 5. March, with a progress line. Per step 0 .. the last, the seconds of the scheme's products
  //    K u_n, M w_n that the next right side reads (inside the step's clock; step 0: 0, formed
  //    with the scheme), a column of case.hist and steps.csv.
  std::vector<double> products{0};
  const std::string label =
      "backward-euler" + (contact ? " + " + solver.parameters.method : std::string());
  const MarchHistory history =
      march_with_progress(march, time, label, [&](const StepRecord& s, const DynamicState&) {
        products.push_back(scheme.products_seconds());
        char detail[96];
        std::snprintf(detail, sizeof detail, "t = %.6g  E = %.6g  Newton %d", s.time,
                      s.energy.total + s.energy.interface, s.iterations);
        return std::string(detail) +
               (step_solver ? "  outer " + std::to_string(int(convexification.outer.back())) : "");
      });
  const auto [iterations, most] = newton_iterations(history);

  // 6. case.hist and steps.csv (both atomic), and a summary line: the host's, every rank done. A
  //    failed step's products were not formed: 0.
  if (!writes_outputs()) return;
  HistoryInfo info = velocity_history_info(time, solver, march, elements ? &*elements : nullptr);
  info.seconds = history.seconds;
  info.mass = to_string(time.mass);
  products.resize(history.steps.size(), 0.0);
  info.step_columns = {{"step_seconds_products", products}};
  add_convexification_columns(convexification, info);
  write_hist(args.ds_path("hist"), history, reduced, info, datafile.title());
  const auto csv_path = args.outdir / "steps.csv";
  write_file_atomically(csv_path, steps_csv(history, info));
  std::printf("sig-march: %s (%s, mass %s), %d free dofs, %d contact nodes, %zu/%d steps of k = "
              "%g, factorizations: %d sparse + %d dense, Newton iterations %d (at most %d a "
              "step), convexification %.0f (at most %.0f a step), E0 = %.9g, E = %.9g, "
              "factorize %.3f s, march %.3f s%s\n",
              label.c_str(), solver_words(solver.backend, info.ordering, info.ranks).c_str(),
              to_string(time.mass).c_str(), reduced.num_free(), contact ? contact->size() : 0,
              history.steps.size() - 1, time.steps, time.k, march.sparse_factorizations(),
              march.dense_factorizations(), iterations, most, convexification.total(),
              convexification.most(),
              history.steps.front().energy.total + history.steps.front().energy.interface,
              history.steps.back().energy.total + history.steps.back().energy.interface,
              march.seconds_factorize(), history.seconds,
              history.converged ? "" : " (STOPPED: a step failed)");
  std::cout << args.ds_path("hist").string() << "\n" << csv_path.string() << "\n";
}

} // namespace sig
