// sig-bench-finite-strain DATAFILE [-o OUTDIR] [--repeat K]: how far the large-deformation
// Newton of sig-solve (Scene 7b) is from its floor, both timed in this one process.
//
// Reads the same files and cards as sig-solve (case.nopo, case.mili, case.tae, case.cont; SOLVER,
// LOADSTEPS) and writes nothing but OUTDIR/bench.json:
//  - the solve: K runs (default 3) of solve_finite_strain_stage, as sig-solve runs it; wall
//    seconds of each (the small-strain start included, its own median beside), Newton
//    iterations, convergence, reactions;
//  - the floor of a Newton method on this mesh: the bulk tangent at the final state of the first
//    run, its Dirichlet dofs eliminated (the pattern the Newton matrix is factorized on), with
//    the same backend: one symbolic analysis, then 2K x (numeric factorization + one solve),
//    two after each timed solve; floor = sig::median(factorize + solve) x iterations. The
//    analysis, done once per solve, is reported apart;
//  - one assembly of the hyperelastic force and tangent (median of K, one after each solve) and
//    the number of bulk assemblies of the solve (line-search trials), for the breakdown.
// Non-convergence is reported (converged = false), not an error.
#include "assembly/dirichlet.hpp"
#include "assembly/nonlinear.hpp"
#include "assembly/pattern.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "core/bench.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nopo.hpp"
#include "solver/linear_solver.hpp"
#include "solver/solver_card.hpp"
#include "stages/finite_strain_stage.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string json_list(const std::vector<double>& values) {
  std::ostringstream out;
  out.precision(9);
  out << "[";
  for (std::size_t k = 0; k < values.size(); ++k)
    out << (k ? ", " : "") << values[k];
  out << "]";
  return out.str();
}

} // namespace

int main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-bench-finite-strain",
      .purpose = "Times the large-deformation Newton of sig-solve (scene 7b) K times in one "
                 "process against its floor: one symbolic analysis, then numeric factorization + "
                 "solve of the tangent at the final state, times the Newton iterations. "
                 "Non-convergence is reported, not an error.",
      .reads = {"DATAFILE", "OUTDIR/case.nopo, case.mili, case.tae, case.cont (as sig-solve)"},
      .writes = {"OUTDIR/bench.json (solve seconds of each run and their median, floor, analysis, "
                 "assembly, iterations, reactions)"},
      .cards = sig::stage_cards("bench-finite-strain").cards,
      .usage = "DATAFILE [-o OUTDIR] [--repeat K] [--time-limit SECONDS]",
      .options = {{"--repeat K", "timed runs of the solve (default 3); the floor gets two "
                                 "factorizations + solves after each"}}};
  return sig::run_stage("bench-finite-strain", [&] {
    // 1. Arguments: --repeat K, the rest as every stage.
    const sig::BenchArgs args = sig::parse_bench_args(argc, argv, help);
    const int repeat = args.repeat;
    const sig::Datafile& datafile = args.deck;

    // 2. The SOLVER and LOADSTEPS cards, as sig-solve reads them.
    const sig::SolverCard card = sig::read_solver_card(datafile);
    SIG_VERIFY(datafile.find("CONTACT"), args.datafile.string()
                                             << ": the deck needs a CONTACT card");
    sig::FiniteStrainOptions options;
    options.backend = card.backend;
    options.contact = card.parameters;
    options.load_steps = card.load_steps;
    options.small_strain_start = card.small_strain_start;

    const sig::Mesh mesh = sig::read_nopo(args.ds_path("nopo"));
    sig::require_2d(mesh, "sig-bench-finite-strain", "finite strain");
    const sig::MaterialTable table = sig::read_mili(args.ds_path("mili"));
    SIG_VERIFY(sig::has_hyperelastic_law(table), "the MILI has no hyperelastic law");
    const sig::LinearSystem system = sig::read_tae(args.ds_path("tae"));
    const sig::ContactElements contact = sig::read_cont(args.ds_path("cont"), mesh);

    // 3. The first timed solve: what the report says of the solve, and the floor's final state.
    std::vector<double> solve_seconds, start_seconds;
    const auto timed_solve = [&] {
      sig::FiniteStrainStageResult run =
          sig::solve_finite_strain_stage(mesh, table, system, &contact, options);
      solve_seconds.push_back(run.seconds);
      start_seconds.push_back(run.solution.start.seconds);
      return run;
    };
    const sig::FiniteStrainStageResult first = timed_solve();
    const sig::FiniteStrainSolution& solution = first.solution;
    const int iterations = solution.total_iterations();
    int bulk_evaluations = 0;
    for (const sig::LoadStepResult& step : solution.steps)
      bulk_evaluations += step.bulk_evaluations;

    // 4. The floor: the tangent at the final state, the problem's Dirichlet dofs eliminated.
    const sig::SparsityPattern pattern(mesh);
    const Eigen::VectorXd final_u = solution.steps.back().u;
    sig::HyperelasticState state;
    sig::assemble_hyperelastic(mesh, table, pattern, final_u, state);
    sig::LinearSystem tangent;
    tangent.K = state.tangent;
    tangent.f = Eigen::VectorXd::Ones(tangent.K.rows());
    tangent.dirichlet_dofs = system.dirichlet_dofs;
    tangent.dirichlet_values = Eigen::VectorXd::Zero(system.dirichlet_values.size());
    const sig::ReducedSystem reduced = sig::reduce(tangent);
    const auto solver = sig::make_linear_solver(
        options.backend, sig::backend_traits(options.backend).symmetric_kind());
    const sig::Stopwatch analysis_clock;
    solver->analyze(reduced.K);
    const double analyze_seconds = analysis_clock.seconds();
    // Two floor samples and one assembly after each solve: the machine's drift (a shared host)
    // then moves the solves and the floor together, and the floor's median has 2K samples.
    std::vector<double> factor_solve_seconds, assembly_seconds;
    const auto time_floor = [&] {
      const sig::Stopwatch assembly_clock;
      sig::assemble_hyperelastic(mesh, table, pattern, final_u, state);
      assembly_seconds.push_back(assembly_clock.seconds());
      for (int sample = 0; sample < 2; ++sample) {
        const sig::Stopwatch clock;
        solver->factorize(reduced.K);
        const Eigen::VectorXd x = solver->solve(reduced.f);
        factor_solve_seconds.push_back(clock.seconds());
        SIG_VERIFY(x.allFinite(), "the floor solve gave a non-finite solution");
      }
    };
    time_floor();
    for (int k = 1; k < repeat; ++k) {
      timed_solve();
      time_floor();
    }
    const double floor = sig::median(factor_solve_seconds) * iterations;

    // 5. Report.
    const std::filesystem::path json = args.outdir / "bench.json";
    std::ofstream out(json);
    out.precision(9);
    out << "{\n  \"method\": \"" << options.contact.method << "\",\n  \"backend\": \""
        << options.backend << "\",\n  \"dofs\": " << solution.unknowns
        << ",\n  \"free_dofs\": " << reduced.num_free()
        << ",\n  \"converged\": " << (solution.converged() ? "true" : "false")
        << ",\n  \"iterations\": " << iterations
        << ",\n  \"bulk_evaluations\": " << bulk_evaluations
        << ",\n  \"reaction_x\": " << first.reaction_x
        << ",\n  \"reaction_y\": " << first.reaction_y
        << ",\n  \"reaction_moment\": " << first.reaction_moment
        << ",\n  \"solve_seconds\": " << json_list(solve_seconds)
        << ",\n  \"solve_seconds_median\": " << sig::median(solve_seconds) << ",\n  \"start\": \""
        << solution.start.name() << "\",\n  \"start_iterations\": " << solution.start.iterations
        << ",\n  \"start_seconds_median\": " << sig::median(start_seconds)
        << ",\n  \"analyze_seconds\": " << analyze_seconds
        << ",\n  \"factor_solve_seconds\": " << json_list(factor_solve_seconds)
        << ",\n  \"factor_solve_seconds_median\": " << sig::median(factor_solve_seconds)
        << ",\n  \"assembly_seconds_median\": " << sig::median(assembly_seconds)
        << ",\n  \"floor_seconds\": " << floor << "\n}\n";
    SIG_VERIFY(out.good(), json.string() << ": cannot write");
    std::cout << "sig-bench-finite-strain: " << options.contact.method << " (" << options.backend
              << "), " << solution.unknowns << " dofs, "
              << (solution.converged() ? "converged" : "NOT converged (Nv)") << " in " << iterations
              << " iterations; solve median " << sig::median(solve_seconds) << " s; floor "
              << sig::median(factor_solve_seconds) << " s x " << iterations << " = " << floor
              << " s (analysis " << analyze_seconds << " s); ratio "
              << sig::median(solve_seconds) / floor << " -> " << json.string() << "\n";
  });
}
