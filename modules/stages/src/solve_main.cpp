// sig-solve DATAFILE [-o OUTDIR]: the static solution, written to OUTDIR/case.b.
//
//   SOLVER method=linear|alm|penalty|pdas|projection linear=cholmod|umfpack|mumps
//          r= gamma= c= eps= maxit=
//
//   LOADSTEPS n= start=small-strain|rest   (hyperelastic laws only; default 1, small-strain)
//
//   INITIAL u=ux,uy [region=]   (contact decks: the first iterate of the contact Newton)
//
// Reads case.tae (sig-assemble) and, when the datafile has a CONTACT card, case.cont
// (sig-contact). When the MILI (case.mili) has a hyperelastic law the problem is solved in large
// deformation (stages/finite_strain_stage.hpp): Newton in LOADSTEPS steps up to the imposed
// displacements of case.tae, with per-step results in case.b. Non-convergence of a contact method
// is a result: the stage exits 0 and the DS records converged = 0 with the iteration history ("Nv"
// in the tables).
//
// Under `mpirun -np P` (a small-strain contact deck, linear=mumps) every rank holds the rows of
// K of its nodes (a METIS partition, stages/rank_rows.hpp), read streaming off case.tae, and
// MUMPS factorizes them together, keeping the contact unknowns as its Schur complement on rank
// 0; the small contact problem is solved on the complement every rank receives, and rank 0
// alone writes case.b. A rank that fails ends the job (MPI_Abort): no case.b is written.
#include "stages/stage_mains.hpp"

#include "assembly/initial.hpp"
#include "assembly/loads.hpp"
#include "assembly/rigid_motion.hpp"
#include "assembly/singular_matrix.hpp"
#include "contact/contact_elements.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/phase_times.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "material/mili.hpp"
#include "mesh/nopo.hpp"
#include "solver/mpi_session.hpp"
#include "solver/solver_card.hpp"
#include "stages/augmentation_scale.hpp"
#include "stages/finite_strain_stage.hpp"
#include "stages/rank_rows.hpp"
#include "stages/solution_ds.hpp"

#include <cmath>
#include <iostream>
#include <optional>

namespace sig {

int solve_main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-solve",
      .purpose = "Static solve: linear elasticity, or contact with the SOLVER card's method (alm, "
                 "penalty, pdas, projection) and the laws of case.cont; in large deformation (a "
                 "hyperelastic MATERIAL) Newton in LOADSTEPS steps. A method that does not "
                 "converge is a result: the stage exits 0 and case.b says converged = 0 (\"Nv\").",
      .reads = {"DATAFILE", "OUTDIR/case.tae (sig-assemble)", "OUTDIR/case.mili (sig-material)",
                "OUTDIR/case.cont (sig-contact; with a CONTACT card)",
                "OUTDIR/case.nopo (sig-mesh; large deformation, INITIAL, the norm of the "
                "convexification loop)"},
      .writes = {"OUTDIR/case.b (displacement, multipliers, statuses, iteration history, phase "
                 "times; per load step in large deformation)"},
      .cards = sig::stage_cards("solve").cards};
  const bool distributed = sig::mpi::launched(); // a rank of an mpirun job
  return sig::run_stage_on_ranks("solve", [&] {
    // 1. Arguments and the SOLVER card.
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, help);
    const sig::Datafile& datafile = args.deck;
    const sig::Card* contact_card = datafile.find("CONTACT");
    const bool has_contact = contact_card != nullptr;
    // strategy=, r= and persistency= of CONTACT belong to time marching (sig-march); a static deck
    // has none.
    for (const char* dynamic : {"strategy", "r", "persistency"})
      if (has_contact && contact_card->has(dynamic))
        contact_card->fail(dynamic, std::string("is a field of dynamic contact (sig-march, with a "
                                                "TIME card); a static deck has no strategy: ") +
                                        "remove it (the static method is SOLVER method=, its "
                                        "stiffness SOLVER r=)");
    // The laws in velocity (damped, damped-unilateral) are laws of a march in time.
    if (has_contact && contact_card->has("law")) {
      const std::string law = contact_card->choice("law", sig::normal_law_choices);
      if (sig::ContactLaw{sig::normal_law_named(law)}.in_velocity())
        contact_card->fail("law", "law=" + law +
                                      " is a contact law in velocity: it needs a march in time "
                                      "(TIME scheme=quasistatic, sig-march)");
    }
    if (const sig::Card* ramped = sig::ramped_load_card(datafile))
      ramped->fail("ramp", "a static deck has no time: a load growing with t needs a TIME card "
                           "(sig-march)");
    const sig::SolverCard card = sig::read_solver_card(datafile);
    for (const sig::Card* initial : datafile.all("INITIAL")) {
      for (const char* velocity : {"v", "omega"})
        if (initial->has(velocity))
          initial->fail(velocity, "a static deck has no velocity (INITIAL v=, omega= are for TIME "
                                  "decks)");
      if (!has_contact)
        initial->fail("u", "a static deck without contact is one linear solve: it has no first "
                           "iterate to start from");
    }
    // A static solve has no time, hence no slip rate.
    if (const sig::Card* friction = sig::friction_card_with_law(datafile))
      if (friction->choice("law", sig::friction_law_choices) == "nonmonotone" &&
          friction->choice("of", sig::slip_measure_choices, "slip") == "slip-rate")
        friction->fail("of", "a static solve has no slip rate: of=slip-rate is for a march in "
                             "time (sig-march); use of=slip");
    const std::string& backend = card.backend;
    const sig::ContactSolverParameters& parameters = card.parameters;
    const std::string& method = parameters.method;
    if (distributed) {
      sig::require_mumps_under_mpirun(datafile, backend);
      SIG_VERIFY(has_contact, datafile.path << ": a deck without contact is one linear solve: "
                                               "run it without mpirun");
    }

    // 2. The assembled system, the contact elements and the mesh; every part of the body held
    //    (by the DIRICHLET cards, and by the contact nodes, onto which the solve condenses), and
    //    the words for a matrix that fails to factorize all the same.
    const sig::Mesh mesh = sig::read_nopo(args.ds_path("nopo"));
    const sig::LinearSystem system = sig::read_tae_of_rank(args.ds_path("tae"), mesh);
    std::optional<sig::ContactElements> contact;
    if (has_contact) contact = sig::read_cont(args.ds_path("cont"), mesh);
    if (mesh.dim == 3) {
      // A 3D deck: sig-contact refused the friction laws other than Tresca and Coulomb (issue 26);
      // a hyperelastic one is solved frictionless (the finite-strain bulk in d = 3, issue 28).
      if (!datafile.all("INITIAL").empty())
        datafile.all("INITIAL").front()->fail("u", "an initial displacement in 3D is not "
                                                   "implemented yet (issue 26)");
      if (contact)
        sig::verify_rigid_motions_held_3d(mesh, system.dirichlet_dofs, datafile.path, contact->node,
                                          contact->normal, contact->has_friction());
      else
        sig::verify_rigid_motions_held_3d(mesh, system.dirichlet_dofs, datafile.path);
    } else {
      const std::vector<Eigen::Vector2d> normals =
          contact ? std::vector<Eigen::Vector2d>(contact->normal.begin(), contact->normal.end())
                  : std::vector<Eigen::Vector2d>{};
      const sig::Holds held = contact ? sig::holds_of(system.dirichlet_dofs, contact->node, normals,
                                                      contact->has_friction())
                                      : sig::holds_of(system.dirichlet_dofs);
      sig::verify_rigid_motions_held(mesh, held, datafile.path);
      sig::explain_factorization_failures(
          [deck = datafile.path, outdir = args.outdir, held](const std::string& library) {
            return deck + ": " + sig::explain_failed_factorization(outdir, &held, false, library);
          });
    }

    // 3. Large deformation when a law is hyperelastic (the TAE's K is then unused).
    const sig::MaterialTable table = sig::read_mili(args.ds_path("mili"));
    if (has_contact || sig::has_hyperelastic_law(table))
      sig::verify_total_iterations(datafile, sig::ContactSolverParameters::solve_max_iterations);
    if (sig::has_hyperelastic_law(table)) {
      if (distributed)
        SIG_VERIFY(false, datafile.path << ": the large-deformation solve runs in one process: "
                                           "run it without mpirun");
      if (!datafile.all("INITIAL").empty())
        datafile.all("INITIAL").front()->fail(
            "u", "the large-deformation solve starts from the reference configuration");
      if (const sig::Card* friction = sig::friction_card_with_law(datafile))
        friction->fail("law", "friction in large deformation is not implemented (a hyperelastic "
                              "MATERIAL): the frictional solve is small strain");
      if (std::isfinite(parameters.candidate_gap))
        datafile.find("SOLVER")->fail("candidate_gap",
                                      "is for a small-strain solve: the large-deformation solve "
                                      "follows every contact node");
      sig::FiniteStrainOptions options;
      options.contact = parameters;
      options.backend = backend;
      options.load_steps = card.load_steps;
      options.small_strain_start = card.small_strain_start;
      if (!has_contact) options.contact.method = "pdas"; // no contact nodes: plain Newton
      const sig::FiniteStrainStageResult result = sig::solve_finite_strain_stage(
          mesh, table, system, contact ? &*contact : nullptr, options);
      sig::write_finite_strain_solution(args.ds_path("b"), result, method, backend,
                                        datafile.title());
      const sig::FiniteStrainSolution& s = result.solution;
      std::cout << "sig-solve: finite strain, " << method << " (" << backend << "), " << s.unknowns
                << " dofs, " << s.steps.size() << "/" << options.load_steps << " load steps, "
                << (s.converged() ? "converged" : "NOT converged (Nv)") << " in "
                << s.total_iterations() << " iterations (per step:";
      for (const sig::LoadStepResult& step : s.steps)
        std::cout << " " << step.iterations() << (step.converged ? "" : "Nv");
      std::cout << "), start " << s.start.name();
      if (s.start.fraction > 0 && s.start.fraction < 1) std::cout << " x " << s.start.fraction;
      if (s.start.fraction > 0) std::cout << " (" << s.start.iterations << " iterations)";
      std::cout << ", reaction " << result.reaction_x << "," << result.reaction_y;
      if (mesh.dim == 3)
        std::cout << "," << result.reaction_z;
      else
        std::cout << " moment " << result.reaction_moment;
      std::cout << ", solve " << result.seconds << " s -> " << args.ds_path("b").string() << "\n";
      for (std::size_t k = 0; k < s.steps.size(); ++k)
        if (!s.steps[k].converged)
          std::cout << "sig-solve: Nv, load step " << k + 1 << ": " << s.steps[k].failure << "\n";
      if (!s.converged() && contact) // beside a failure: the parameter far off the scale?
        sig::hint_augmentation_scale(datafile, method, system.K, *contact, false);
      return;
    }

    // 4. Solve, from the INITIAL displacement (the first iterate of the contact Newton).
    sig::refuse_load_steps(datafile, "a small-strain solve is linear in the load (the contact "
                                     "methods solve it whole)");
    sig::StaticSolution solution;
    std::optional<sig::PhaseTimer> timer(std::in_place, "solve");
    if (!has_contact) { // method=linear (read_solver_card)
      sig::warn_unused_iteration_fields(datafile, "a small-strain deck without contact is one "
                                                  "linear solve");
      solution = sig::solve_linear_elasticity(system, backend);
    } else {
      // The mesh gives the first iterate of INITIAL and the norm of V of the convexification
      // loop's test.
      const bool loop = sig::needs_convexification(contact->law);
      SIG_VERIFY(!(loop && distributed),
                 datafile.path << ": the convexification loop of law=nonmonotone runs in one "
                                  "process: run it without mpirun");
      sig::verify_held_contact_components(mesh, datafile, system, *contact, method);
      Eigen::VectorXd start;
      if (!datafile.all("INITIAL").empty()) start = sig::initial_fields(datafile, mesh).u;
      if (std::isfinite(parameters.candidate_gap))
        if (const std::string problem = sig::candidate_zone_problem(*contact); !problem.empty())
          datafile.find("SOLVER")->fail("candidate_gap",
                                        "condenses only the nodes near the obstacle, but " +
                                            problem + ": remove it");
      solution = sig::solve_static_contact(system, *contact, parameters, backend, start,
                                           {card.convexification, loop ? &mesh : nullptr});
    }

    timer.reset();

    // 5. Write case.b and report: rank 0's, every rank done.
    if (!sig::writes_outputs()) return;
    if (distributed) solution.ranks = sig::mpi::size();
    sig::write_solution(args.ds_path("b"), solution, method, backend, datafile.title());
    std::cout << "sig-solve: " << method << " ("
              << sig::solver_words(backend, solution.ordering, solution.ranks) << "), "
              << solution.unknowns << " dofs, "
              << (solution.converged ? "converged" : "NOT converged (Nv)") << " in "
              << solution.history.size() << " iterations";
    if (const auto& loop = solution.convexification) {
      std::cout << " (" << loop->outer_iterations() << " convex solves:";
      for (const sig::OuterRecord& outer : loop->history)
        std::cout << " " << outer.inner_iterations;
      std::cout << (loop->cycle ? ", statuses cycling" : "") << ")";
    }
    std::cout << ", solve " << solution.seconds["solve"] << " s -> " << args.ds_path("b").string()
              << "\n";
    if (!solution.converged) std::cout << "sig-solve: Nv, " << solution.failure << "\n";
    if (!solution.converged && contact)
      sig::hint_augmentation_scale(datafile, method, system.K, *contact, false);
  });
}

} // namespace sig
