// sig-march DATAFILE [-o OUTDIR]: elastodynamics, M a + K u = f, marched from the INITIAL state
// with the scheme of the TIME card, with or without node-to-rigid contact; or, with TIME
// scheme=quasistatic, the quasistatic viscoelastic march in velocity of ch. 5
// (stages/quasistatic_stage.hpp).
//
//   TIME scheme=midpoint|newmark T= k= [output_every=1] [mass=consistent|lumped|emm]
//   INITIAL [u=ux,uy] [v=vx,vy] [region=...]          (3D: three components)
//   CONTACT ... [strategy=signorini|compliance|specific-penalty|two-step|ipm] [r=] [gap=]
//   FRICTION ref= law=coulomb mu= | tresca threshold= | mu1 mu= | mu2 mu=   (of the slip over
//            each step; law=nonmonotone is the backward-Euler march's)
//   SOLVER linear=cholmod|umfpack|mumps maxit=   (K + (4 / k^2) M factorized once; maxit: the
//          strategy's Newton iterations per phase, default 50) [candidate_gap=]  (linear body:
//          only the contact nodes of initial gap at most this condensed, the others watched)
//
// The mesh is 2D or 3D: a 3D body marches the linear schemes (midpoint, Newmark; mass
// consistent, lumped or emm) and the hyperelastic march (Gonzalez's or the midpoint stress)
// with every strategy and the friction laws (coulomb, tresca, mu1, mu2: the slip over a step a
// vector of the node's tangent plane, two slips a node, the force in the disc of radius s, the
// Coulomb cone's section), and the marches in velocity (quasistatic Kelvin-Voigt, backward
// Euler) with their laws and friction of the slip rate (two components a node).
//
// Reads OUTDIR/case.nopo and case.tae (sig-assemble wrote the mass when a MATERIAL has rho > 0),
// with a CONTACT card also case.cont (sig-contact), and writes OUTDIR/case.hist (DS HIST,
// stages/history_io.hpp) and OUTDIR/energy.csv. The contact strategies are those of
// integrator/contact_strategy.hpp (default signorini); r is the foundation stiffness per unit
// area, g (old spelling gap) the depth of the unilateral bound's wall (for ipm: the allowed
// penetration; for mu1 / mu2 the asperities' depth). A linear body (Hooke) and a hyperelastic
// one both take the friction laws (integrator/elastodynamic_march.hpp,
// stages/finite_strain_march.hpp). A step whose Newton fails stops the march: the files hold the
// steps done, HIST converged = 0, a warning is printed and the stage exits 0.
//
// Under `mpirun -np P` (the linear body's marches: midpoint and Newmark with every strategy and
// friction law, and the marches in velocity, backward-euler and quasistatic; SOLVER
// linear=mumps) every rank holds the rows of the step matrix's operators (K, M, V, the memory
// terms) of its nodes (a METIS partition, stages/rank_rows.hpp), read streaming off case.tae or
// its parts, and MUMPS factorizes the step matrix over them once, keeping the contact unknowns
// as its Schur complement on rank 0 (integrator/dynamic_contact.hpp,
// integrator/linear_contact_march.hpp: one condensation for both). Each step's right side is
// formed from every rank's rows (the products summed over the ranks), the contact problem of
// the step (the strategy's or the Newton's, and the convexification loop of FRICTION
// law=nonmonotone) is solved on the complement every rank receives, and rank 0 alone writes
// case.hist and energy.csv or steps.csv, which record the ranks, once every rank is done. A rank
// that fails ends the job (MPI_Abort): no file is written. Refused under mpirun: a hyperelastic
// body (MATERIAL law=: its Newton matrix is assembled again at every iteration from the whole
// state, on one process) and mass=emm (TIME mass=: the Equivalent Mass Matrix is built from the
// whole mass's moments and checked positive definite as a whole).
#include "stages/stage_mains.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/singular_matrix.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "contact/obstacle.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "integrator/contact_strategy.hpp"
#include "integrator/elastodynamic_march.hpp"
#include "integrator/time_scheme.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nopo.hpp"
#include "solver/mpi_session.hpp"
#include "solver/solver_card.hpp"
#include "stages/augmentation_scale.hpp"
#include "stages/contact_card.hpp"
#include "stages/dynamic_stage.hpp"
#include "stages/finite_strain_march.hpp"
#include "stages/finite_strain_stage.hpp"
#include "stages/history_io.hpp"
#include "stages/march_inputs.hpp"
#include "stages/march_stage.hpp"
#include "stages/march_tables.hpp"
#include "stages/quasistatic_stage.hpp"
#include "stages/rank_rows.hpp"
#include "stages/time_card.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

namespace sig {

int march_main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-march",
      .purpose = "Time marching of elastodynamics, M a + K u = f, from the INITIAL state with the "
                 "scheme of the TIME card (K + (4/k^2) M factorized once), with node-to-rigid "
                 "contact by the CONTACT card's strategy and the friction of the FRICTION card "
                 "(coulomb, tresca, mu1, mu2, of the slip over each step); a hyperelastic body "
                 "(MATERIAL law=svk|ciarlet-geymonat) marches in large deformation by the "
                 "midpoint rule with "
                 "the stress of TIME stress= (Gonzalez's by default), each step a Newton method "
                 "with the strategy's phases and friction; or (scheme=quasistatic) the quasistatic "
                 "Kelvin-Voigt march in velocity of ch. 5 with contact laws in velocity, its step "
                 "matrix factorized and condensed once (case.hist, steps.csv); or "
                 "(scheme=backward-euler) the viscoelastodynamic march in velocity of ch. 6, "
                 "(M/k + C + k K) factorized and condensed once, contact laws of the displacement "
                 "and friction of the slip rate, with the convexification loop in every step for "
                 "FRICTION law=nonmonotone. A step whose Newton "
                 "fails stops the "
                 "march: the files hold the steps done, a warning is printed and the stage exits "
                 "0. A progress line shows the step, time steps per second and the time left. "
                 "On a 3D mesh: the linear schemes (midpoint, Newmark; consistent, lumped or EMM "
                 "mass) and the hyperelastic march with every strategy and friction law (the "
                 "Coulomb cone, two slips a node), the quasistatic and backward-Euler marches "
                 "in velocity with their friction laws (two slip rates a node); "
                 "SOLVER candidate_gap= condenses only the contact nodes near the obstacle. "
                 "Under mpirun -np P the linear body's marches (midpoint, newmark, "
                 "backward-euler, quasistatic; SOLVER linear=mumps) factorize their step matrix "
                 "by MUMPS over the ranks, each holding the rows of its METIS part of the mesh, "
                 "the contact unknowns its Schur complement; the hyperelastic march and "
                 "mass=emm run in one process.",
      .reads = {"DATAFILE", "OUTDIR/case.nopo (sig-mesh)",
                "OUTDIR/case.tae (sig-assemble; a MATERIAL with rho > 0 gives the mass)",
                "OUTDIR/case.mili (sig-material: the laws, hyperelastic or not)",
                "OUTDIR/case.cont (sig-contact; with a CONTACT card)"},
      .writes =
          {"OUTDIR/case.hist (one layout for every march: kept states, per step energies and "
           "Newton iterations, contact pressures; the marches in velocity: per step the contact "
           "velocities, forces and statuses)",
           "OUTDIR/energy.csv (one row per step: energies, contact work and its split into "
           "interface, friction and wall work, penetration, active nodes, Newton "
           "iterations, the contact forces' sums)",
           "OUTDIR/steps.csv (quasistatic, backward-euler: one row per step: Newton iterations, "
           "status counts, largest velocity, normal displacement and pressure; "
           "backward-euler: the energies and the convexification counts)"},
      .cards = sig::stage_cards("march").cards};
  const bool distributed = sig::mpi::launched(); // a rank of an mpirun job
  return sig::run_stage_on_ranks("sig-march", [&] {
    // 1. Command line and cards: TIME, INITIAL, CONTACT (strategy, r, gap), SOLVER (backend,
    // maxit).
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, help);
    const sig::Datafile& datafile = args.deck;
    sig::refuse_load_steps(datafile, "a march's loads follow the time of the TIME card");
    const sig::Card* contact = datafile.find("CONTACT");
    const sig::TimeParameters time =
        sig::time_parameters(datafile.require("TIME"), contact != nullptr);
    const sig::TimeSchemeTraits scheme = sig::time_scheme_traits(time.scheme);
    // A step matrix that fails to factorize: a part of the body held by nothing, or by its mass
    // alone (assembly/singular_matrix.hpp).
    sig::explain_factorization_failures(
        [deck = datafile.path, outdir = args.outdir,
         inertia = scheme.march != sig::MarchKind::quasistatic](const std::string& library) {
          return deck + ": " + sig::explain_failed_factorization(outdir, nullptr, inertia, library);
        });
    if (scheme.march == sig::MarchKind::quasistatic) {
      sig::run_quasistatic_march(args, datafile, time);
      return;
    }
    if (scheme.march == sig::MarchKind::viscoelastodynamics) {
      sig::run_backward_euler_march(args, datafile, time);
      return;
    }
    const sig::Card* solver_card = datafile.find("SOLVER");
    sig::warn_unused_solver_fields(solver_card);
    // A hyperelastic body marches in large deformation (stages/finite_strain_march.hpp).
    const sig::MaterialTable materials = sig::read_mili(args.ds_path("mili"));
    const bool hyperelastic = sig::has_hyperelastic_law(materials);
    if (contact != nullptr || hyperelastic)
      sig::verify_total_iterations(datafile, sig::ContactStrategyParameters{}.max_iterations,
                                   time.steps);
    const sig::Card& time_card = datafile.require("TIME");
    if (!hyperelastic && time_card.has("stress"))
      time_card.fail("stress", "is the stress of a hyperelastic time step: the linear midpoint "
                               "rule conserves the energy as it is (remove stress=)");
    if (hyperelastic && !scheme.large_deformation)
      time_card.fail("scheme",
                     "a hyperelastic body marches by the midpoint rule (scheme=midpoint)");
    // Under mpirun: the linear body, its step matrix factorized by MUMPS over the ranks.
    if (distributed && hyperelastic)
      datafile.all("MATERIAL")
          .front()
          ->fail("law",
                 "a hyperelastic body marches in one process: its Newton matrix is assembled "
                 "again at every iteration from the whole state (run sig-march without mpirun, "
                 "or give the body law=hooke)");
    if (distributed && time.mass == sig::MassChoice::emm)
      time_card.fail("mass", "mass=emm marches in one process: the Equivalent Mass Matrix is "
                             "built from the whole mass's moments and checked positive definite "
                             "as a whole (run sig-march without mpirun, or take mass=consistent "
                             "or lumped)");
    const std::string default_backend = hyperelastic ? "mumps" : "cholmod";
    const std::string backend =
        solver_card
            ? solver_card->choice("linear", {"cholmod", "umfpack", "mumps"}, default_backend)
            : default_backend;
    // Gonzalez's tangent and a Coulomb coupling make the step matrix of a hyperelastic march
    // unsymmetric (finite_strain_bulk.cpp), which CHOLMOD cannot factorize: said on the card, not
    // by the linear solver.
    if (distributed) sig::require_mumps_under_mpirun(datafile, backend);
    if (hyperelastic && backend == "cholmod") {
      const bool friction = sig::friction_card_with_law(datafile) != nullptr;
      if (time.stress == sig::AlgorithmicStress::gonzalez || friction)
        solver_card->fail("linear",
                          std::string("cholmod factorizes symmetric matrices only, and the step "
                                      "matrix of a hyperelastic march is not symmetric (") +
                              (friction ? "friction" : "TIME stress=gonzalez") +
                              "): use umfpack or mumps (the default)");
    }
    sig::ContactHistoryInfo strategy_info;
    sig::ContactStrategyParameters strategy_parameters;
    if (const sig::Card* friction = sig::friction_card_with_law(datafile);
        friction && friction->choice("law", sig::friction_law_choices) == "nonmonotone")
      friction->fail(
          "law", "law=nonmonotone needs its convexification loop in every step, which "
                 "only the marches in velocity run (TIME scheme=backward-euler or quasistatic): "
                 "coulomb, tresca, mu1 or mu2 with scheme=" +
                     time.scheme);
    if (contact != nullptr) {
      strategy_info = sig::contact_history_info(*contact);
      strategy_parameters = sig::contact_strategy_parameters(*contact, solver_card);
    }

    // 2. Mesh and assembled system (under mpirun this rank's rows of K and M,
    //    stages/rank_rows.hpp); a dynamic case needs a mass.
    const sig::Mesh mesh = sig::read_nopo(args.ds_path("nopo"));
    const sig::LinearSystem system =
        sig::read_tae_of_rank(args.ds_path("tae"), mesh, /*march=*/true);
    if (system.M.nonZeros() == 0)
      throw sig::InputError(datafile.path, 0, "rho",
                            "every MATERIAL has density 0: a dynamic case (TIME card) needs a "
                            "mass, give the MATERIAL cards rho > 0");

    // 3. Dirichlet elimination (constant imposed values, zero imposed velocity) and the initial
    //    state on the free dofs.
    const sig::ReducedSystem reduced = sig::reduce_on_ranks(system);
    const sig::InitialFields initial_full = sig::initial_fields(datafile, mesh);
    sig::DynamicState initial;
    initial.time = 0.0;
    initial.u = reduced.restrict(initial_full.u);
    initial.v = reduced.restrict(initial_full.v);

    // 4. The contact elements of case.cont and the mass (EMM included).
    // SOLVER candidate_gap=: only the nodes near the obstacle condensed, the others watched.
    std::optional<sig::MarchContactZone> zone;
    if (contact != nullptr)
      zone = sig::march_contact_zone(sig::read_cont(args.ds_path("cont"), mesh), system,
                                     solver_card, hyperelastic);
    const sig::ContactElements* elements = zone ? &zone->condensed : nullptr;
    const Eigen::SparseMatrix<double> mass =
        sig::mass_matrix(system, time.mass, mesh, elements ? elements->node : std::vector<int>{});
    std::unique_ptr<sig::ContactStrategy> strategy;
    if (elements)
      strategy = sig::make_contact_strategy(strategy_info.strategy, strategy_parameters);

    // 5. March, with a progress line: step / steps, time, total energy.
    const std::string label =
        time.scheme + (hyperelastic ? " (" + sig::to_string(time.stress) + " stress)" : "") +
        (contact != nullptr ? " + " + strategy_info.strategy : std::string());
    const auto report = [](const sig::StepRecord& record, const sig::DynamicState& state) {
      char detail[96];
      std::snprintf(detail, sizeof detail, "t = %.6g  E = %.12g", state.time, record.energy.total);
      return std::string(detail);
    };
    sig::Stopwatch clock;
    sig::MarchHistory history;
    std::string ordering; // MUMPS's, of the linear body's step matrix
    if (hyperelastic) {
      // On the full dofs, the Dirichlet values held: the history is restricted afterwards.
      std::unique_ptr<sig::Obstacle> obstacle;
      sig::FiniteStrainProblem problem =
          sig::finite_strain_problem(mesh, materials, system, elements, obstacle);
      problem.mass = &mass;
      problem.time_step = time.k;
      problem.stress = time.stress;
      sig::HyperelasticMarchOptions options;
      options.backend = backend;
      options.eps = strategy_parameters.eps;
      options.max_iterations = strategy_parameters.max_iterations;
      sig::DynamicState full{0.0, reduced.expand(initial.u), reduced.expand(initial.v)};
      for (int dof : system.dirichlet_dofs)
        full.v[dof] = 0.0; // expand() puts the imposed values there
      sig::HyperelasticSteps steps(problem, strategy.get(), options, full);
      history = sig::march_with_progress(steps, time, label, report);
      for (sig::DynamicState& s : history.outputs)
        s = sig::DynamicState{s.time, reduced.restrict(s.u), reduced.restrict(s.v)};
    } else {
      // The scheme's step operator K + (4 / k^2) M, factorized once by the march (with contact,
      // its contact components the Schur complement: integrator/dynamic_contact.hpp).
      sig::Elastodynamics problem = sig::reduced_elastodynamics(reduced, mass);
      problem.rank_rows = system.rank_rows;
      auto scheme = sig::make_time_scheme(time.scheme, std::move(problem), time.k, backend);
      std::optional<sig::ContactBoundary> boundary;
      if (zone) boundary = sig::contact_boundary(*zone, mesh, reduced);
      std::optional<sig::ElastodynamicSteps> steps;
      if (boundary)
        steps.emplace(*scheme, *boundary, *strategy, initial);
      else
        steps.emplace(*scheme, initial);
      history = sig::march_with_progress(*steps, time, label, report);
      ordering = steps->ordering();
    }
    const double seconds = clock.seconds();
    if (!sig::writes_outputs()) return;

    // 6. Write case.hist and energy.csv (both atomic) and report the energy drift.
    sig::HistoryInfo info = sig::history_info(time, backend, elements);
    info.mass = sig::to_string(time.mass);
    if (hyperelastic) info.stress = sig::to_string(time.stress);
    info.seconds = seconds;
    info.ordering = ordering;
    info.ranks = sig::mpi::size();
    if (elements) info.strategy = strategy_info;
    // A linear contact march's steps in free flight, 1 a step (0 at step 0: none taken): the
    // predictor was the step, no Newton iteration and no force.
    int free_steps = 0;
    if (elements && !hyperelastic) {
      std::vector<double> free(history.steps.size(), 0.0);
      for (std::size_t s = 0; s < history.steps.size(); ++s)
        free[s] = history.steps[s].free_flight ? 1.0 : 0.0;
      free_steps = static_cast<int>(std::count(free.begin(), free.end(), 1.0));
      info.step_columns = {{"free_flight", std::move(free)}};
    }
    sig::write_hist(args.ds_path("hist"), history, reduced, info, datafile.title());
    const auto csv_path = args.outdir / "energy.csv";
    sig::write_file_atomically(csv_path, sig::energy_csv(history));
    const double e0 = history.steps.front().energy.total;
    double drift = 0.0, penetration = 0.0;
    for (std::size_t s = 0; s < history.steps_done(); ++s) {
      const sig::EnergyRecord& r = history.steps[s].energy;
      drift = std::max(drift, std::abs(r.total - r.external_work - r.contact_work - e0));
      penetration = std::max(penetration, r.max_penetration);
    }
    const std::string free_words =
        info.step_columns.empty() ? "" : ", free flight " + std::to_string(free_steps) + " steps";
    std::printf(
        "sig-march: %s, mass %s (%s), %d free dofs, %zu/%d steps of k = %g, %zu states "
        "kept, E0 = %.12g, max |E - W - Wc - E0| = %.3g, max penetration %.6g, %.3f s%s%s\n",
        label.c_str(), sig::to_string(time.mass).c_str(),
        sig::solver_words(backend, ordering, info.ranks).c_str(), reduced.num_free(),
        history.steps_done() - 1, time.steps, time.k, history.outputs.size(), e0, drift,
        penetration, seconds, free_words.c_str(),
        history.converged ? "" : " (STOPPED: Newton failed)");
    std::cout << args.ds_path("hist").string() << "\n" << csv_path.string() << "\n";
    // Beside a stop: every strategy's Newton is PDAS's, with SOLVER gamma= (from the whole K:
    // not under mpirun).
    if (!history.converged && elements && !distributed)
      sig::hint_augmentation_scale(datafile, "pdas", system.K, *elements, true);
  });
}

} // namespace sig
