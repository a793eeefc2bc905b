// sig-bench-quasistatic DATAFILE [-o OUTDIR] [--repeat K]: times the quasistatic march of
// sig-march (TIME scheme=quasistatic) K times in one process against its floor, and writes
// OUTDIR/bench.json:
//  - the march: the setup (frames, one sparse factorization and the Schur complement of the step
//    matrix, the condensed problem's Cholesky) and the steps apart, every step's wall time, and
//    its parts: the scheme's right side, the contact problem on the condensed bulk, the rest (the
//    right side's condensation and the velocity's expansion: with MUMPS one solve split in two);
//  - the floors: one forward-backward solve with the step matrix factorized by the same backend
//    (the project's solver: supernodal for CHOLMOD) and, for CHOLMOD, by a simplicial LL^T (the
//    faster of the two on these 2D meshes, solver/cholmod_simplicial.hpp), the medians of many;
//  - the counts: sparse and dense factorizations, the tail systems factorized by the condensed
//    bulk, Newton iterations.
// The runs and the floor go round robin, so that load bursts on a shared machine fall on both.
#include "core/bench.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/json.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "integrator/kelvin_voigt_scheme.hpp"
#include "integrator/linear_contact_march.hpp"
#include "integrator/time_scheme.hpp"
#include "solver/cholmod_simplicial.hpp"
#include "solver/linear_solver.hpp"
#include "stages/march_inputs.hpp"
#include "stages/quasistatic_stage.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-bench-quasistatic",
      .purpose = "Times the quasistatic march of sig-march (scene 5) K times in one process "
                 "against its floor, one forward-backward solve with the factorized step matrix; "
                 "counts the factorizations.",
      .reads = {"DATAFILE", "OUTDIR/case.nopo, case.mili, case.tae, case.cont (as sig-march)"},
      .writes = {"OUTDIR/bench.json (setup and march seconds per run, medians per step and of "
                 "its parts, the floor, the ratio, the factorization and iteration counts)"},
      .cards = sig::stage_cards("bench-quasistatic").cards,
      .usage = "DATAFILE [-o OUTDIR] [--repeat K] [--time-limit SECONDS]",
      .options = {{"--repeat K", "timed marches (default 3)"}}};
  return sig::run_stage("bench-quasistatic", [&] {
    const sig::BenchArgs args = sig::parse_bench_args(argc, argv, help);
    const int repeat = args.repeat;
    const sig::Datafile& datafile = args.deck;
    const sig::TimeParameters time = sig::time_parameters(datafile.require("TIME"), true);
    SIG_VERIFY(sig::time_scheme_traits(time.scheme).march == sig::MarchKind::quasistatic,
               args.datafile.string() << ": the deck's TIME card is not scheme=quasistatic");
    const sig::QuasistaticCase c = sig::read_quasistatic_case(args, datafile);
    const sig::VelocityContact* contact = c.contact ? &*c.contact : nullptr;

    std::vector<double> setup, march, step, right_side, contact_solve, rest_of_step, floor,
        simplicial_floor;
    int iterations = 0, dense = 0, tail = 0, steps_done = 0;
    bool converged = true;
    for (int r = 0; r < repeat; ++r) {
      // One march, from its setup.
      {
        sig::QuasistaticKelvinVoigt scheme(sig::viscoelastic_problem(c.system, c.reduced), time.k,
                                           c.u0);
        const sig::Stopwatch clock;
        sig::LinearContactMarch m(scheme, contact, c.solver.parameters, c.solver.backend);
        setup.push_back(clock.seconds());
        const sig::MarchHistory h = sig::march(m, time.steps, time.steps);
        march.push_back(h.seconds);
        converged = converged && h.converged;
        iterations = 0;
        for (std::size_t n = 1; n < h.steps.size(); ++n) {
          const sig::StepSeconds& s = h.steps[n].seconds;
          step.push_back(s.total);
          right_side.push_back(s.right_side);
          contact_solve.push_back(s.contact);
          rest_of_step.push_back(s.total - s.right_side - s.contact);
          iterations += h.steps[n].iterations;
        }
        steps_done = static_cast<int>(h.steps.size()) - 1;
        dense = m.dense_factorizations();
        tail = m.tail_factorizations();
      }
      // The floor: forward-backward solves with the step matrix factorized by the same backend.
      const sig::QuasistaticKelvinVoigt scheme(sig::viscoelastic_problem(c.system, c.reduced),
                                               time.k, c.u0);
      const auto solver = sig::make_linear_solver(c.solver.backend, sig::MatrixKind::spd);
      solver->factorize(scheme.step_matrix());
      const Eigen::VectorXd b = scheme.right_side(1);
      for (int k = 0; k < 20; ++k) {
        const sig::Stopwatch clock;
        const Eigen::VectorXd x = solver->solve(b);
        floor.push_back(clock.seconds());
        SIG_VERIFY(x.allFinite(), "the floor solve gave a non-finite solution");
      }
      // A Cholesky backend (CHOLMOD) against its simplicial LL^T as well.
      if (sig::backend_traits(c.solver.backend).cholesky) {
        Eigen::SparseMatrix<double> S = scheme.step_matrix();
        S.makeCompressed();
        sig::CholmodSimplicialSolver simplicial(S);
        for (int k = 0; k < 20; ++k) {
          const sig::Stopwatch clock;
          const Eigen::VectorXd x = simplicial.solve(b);
          simplicial_floor.push_back(clock.seconds());
          SIG_VERIFY(x.allFinite(), "the simplicial floor solve gave a non-finite solution");
        }
      }
    }

    sig::Json json = sig::Json::object();
    json.set("backend", c.solver.backend);
    json.set("method", contact ? c.solver.parameters.method : "linear");
    json.set("free_dofs", c.reduced.num_free());
    json.set("dofs", c.system.num_dofs());
    json.set("contact_nodes", contact ? contact->size() : 0);
    json.set("steps", time.steps);
    json.set("steps_done", steps_done);
    json.set("converged", converged);
    json.set("newton_iterations", iterations);
    json.set("sparse_factorizations", 1);
    json.set("dense_factorizations", dense);
    json.set("tail_factorizations", tail);
    json.set("repeat", repeat);
    json.set("setup_seconds", sig::Json::array_of(setup));
    json.set("march_seconds", sig::Json::array_of(march));
    json.set("setup_seconds_median", sig::median(setup));
    json.set("march_seconds_median", sig::median(march));
    json.set("step_seconds_median", sig::median(step));
    json.set("right_side_seconds_median", sig::median(right_side));
    json.set("contact_seconds_median", sig::median(contact_solve));
    json.set("condense_expand_seconds_median", sig::median(rest_of_step));
    json.set("floor_solve_seconds_median", sig::median(floor));
    json.set("step_over_solve", sig::median(step) / sig::median(floor));
    if (!simplicial_floor.empty()) {
      json.set("simplicial_floor_solve_seconds_median", sig::median(simplicial_floor));
      json.set("step_over_simplicial_solve", sig::median(step) / sig::median(simplicial_floor));
    }
    const std::filesystem::path path = args.outdir / "bench.json";
    sig::write_file_atomically(path, json.dump() + "\n");
    std::cout << json.dump() << "\n" << path.string() << "\n";
  });
}
