#include "stages/quasistatic_stage.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/initial.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "integrator/kelvin_voigt_scheme.hpp"
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

// The cards a quasistatic deck must not have, each refused on its line and field.
void refuse_other_models(const Datafile& datafile) {
  if (const Card* contact = datafile.find("CONTACT")) {
    for (const char* dynamic : {"strategy", "r"})
      if (contact->has(dynamic))
        contact->fail(dynamic, "is a field of the dynamic contact strategies; a quasistatic "
                               "march takes its contact law in velocity (law=damped or "
                               "damped-unilateral) and its method from SOLVER");
    const std::string law = contact->choice("law", normal_law_choices);
    if (!ContactLaw{normal_law_named(law)}.in_velocity())
      contact->fail("law", "law=" + law +
                               " is a law of the displacement; the quasistatic march is in "
                               "velocity and needs a contact law in velocity: law=damped cn= or "
                               "law=damped-unilateral cn= g=");
  }
  if (const Card* friction = datafile.find("FRICTION"))
    if (friction->choice("law", friction_law_choices) == "nonmonotone" &&
        friction->choice("of", slip_measure_choices) != "slip-rate")
      friction->fail("of", "the quasistatic march's tangential variable is the slip rate w_t: "
                           "give of=slip-rate");
  for (const Card* initial : datafile.all("INITIAL"))
    if (initial->has("v"))
      initial->fail("v", "the quasistatic march has no initial velocity: its first velocity "
                         "w_0 is 0 (ALGORITHMS.md C8); give u= only");
}

} // namespace

QuasistaticCase read_quasistatic_case(const StageArgs& args, const Datafile& datafile) {
  // 1. Cards: what the march does not model, then SOLVER (method, backend, Newton options).
  refuse_other_models(datafile);
  QuasistaticCase c;
  c.solver = read_solver_card(datafile, /*march=*/true);
  if (mpi::launched()) require_mumps_under_mpirun(datafile, c.solver.backend);

  // 2. Mesh, laws, assembled system (elastic K, viscous V, memory terms, loads in time; under
  //    mpirun this rank's rows of the matrices, stages/rank_rows.hpp).
  // 2D and 3D on one code path: a 3D node's slip rate has two components, along its tangents t1
  // and t2, and its friction force lies in the Coulomb cone's disc (contact/contact_kernel.hpp).
  const Mesh mesh = read_nopo(args.ds_path("nopo"));
  for (const SubdomainMaterial& m : read_mili(args.ds_path("mili")).entries)
    if (m.hyperelastic)
      datafile.all("MATERIAL")
          .front()
          ->fail("law", "a hyperelastic law is large deformation; the quasistatic march is small "
                        "strain (law=hooke or kelvin-voigt)");
  c.system = read_tae_of_rank(args.ds_path("tae"), mesh, /*march=*/true);
  c.reduced = reduce_on_ranks(c.system);
  c.u0 = c.reduced.restrict(initial_fields(datafile, mesh).u);

  // 3. The contact boundary.
  if (datafile.find("CONTACT") != nullptr) {
    c.elements = read_cont(args.ds_path("cont"), mesh);
    c.contact = velocity_contact(*c.elements, c.reduced);
    if (c.elements->gap.maxCoeff() > 0)
      log_warning("the laws in velocity ignore the initial gap (up to " +
                  std::to_string(c.elements->gap.maxCoeff()) +
                  "): they act on the normal velocity from t = 0, as if Gamma3 lay on the "
                  "obstacle (the thesis's model (5.5))");
  }
  return c;
}

void run_quasistatic_march(const StageArgs& args, const Datafile& datafile,
                           const TimeParameters& time) {
  QuasistaticCase c = read_quasistatic_case(args, datafile);
  if (c.elements)
    verify_total_iterations(datafile, ContactSolverParameters::solve_max_iterations, time.steps);
  const SolverCard& solver = c.solver;
  const bool has_contact = c.contact.has_value();
  const std::optional<ContactElements>& elements = c.elements;
  const std::optional<VelocityContact>& contact = c.contact;
  // 1. The scheme and the march: the step matrix factorized and condensed here, once.
  QuasistaticKelvinVoigt scheme(viscoelastic_problem(c.system, c.reduced), time.k, c.u0);
  // The step solver: the one Newton driver, or the convexification loop of a nonmonotone law.
  ConvexificationRecords convexification;
  const StepSolver step_solver =
      convexification_step(scheme, contact ? &*contact : nullptr, solver, convexification);
  LinearContactMarch march(scheme, contact ? &*contact : nullptr, solver.parameters, solver.backend,
                           step_solver);

  // 2. March, with a progress line.
  const std::string label = "quasistatic" + (has_contact ? " + " + solver.parameters.method : "");
  const MarchHistory history =
      march_with_progress(march, time, label, [](const StepRecord& s, const DynamicState&) {
        char detail[96];
        std::snprintf(detail, sizeof detail, "t = %.6g  Newton %d", s.time, s.iterations);
        return std::string(detail);
      });
  const auto [iterations, most] = newton_iterations(history);

  // 3. case.hist and steps.csv (both atomic), and a summary line: the host's, every rank done.
  if (!writes_outputs()) return;
  HistoryInfo info = velocity_history_info(time, solver, march, elements ? &*elements : nullptr);
  info.seconds = history.seconds;
  add_convexification_columns(convexification, info);
  write_hist(args.ds_path("hist"), history, c.reduced, info, datafile.title());
  const auto csv_path = args.outdir / "steps.csv";
  write_file_atomically(csv_path, steps_csv(history, info));
  // The loop's counts where it ran: the summary of 2D decks without it stays as it was.
  char outer[96] = "";
  if (step_solver)
    std::snprintf(outer, sizeof outer, ", convexification %.0f (at most %.0f a step)",
                  convexification.total(), convexification.most());
  std::printf("sig-march: %s (%s), %d free dofs, %d contact nodes, %zu/%d steps of k = %g, "
              "factorizations: %d sparse + %d dense, Newton iterations %d (at most %d a step)%s, "
              "factorize %.3f s, march %.3f s%s\n",
              label.c_str(), solver_words(solver.backend, info.ordering, info.ranks).c_str(),
              c.reduced.num_free(), contact ? contact->size() : 0, history.steps.size() - 1,
              time.steps, time.k, march.sparse_factorizations(), march.dense_factorizations(),
              iterations, most, outer, march.seconds_factorize(), history.seconds,
              history.converged ? "" : " (STOPPED: Newton failed)");
  std::cout << args.ds_path("hist").string() << "\n" << csv_path.string() << "\n";
}

} // namespace sig
