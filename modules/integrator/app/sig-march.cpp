// sig-march DATAFILE [-o OUTDIR]: elastodynamics without contact, M a + K u = f, marched from
// the INITIAL state with the scheme of the TIME card.
//
//   TIME scheme=midpoint|newmark T= k= [output_every=1] [mass=consistent|lumped|emm]
//   INITIAL [u=ux,uy] [v=vx,vy] [region=...]
//   SOLVER linear=cholmod|umfpack|mumps   (the factorization of K + (4 / k^2) M, once)
//
// Reads OUTDIR/case.nopo and case.tae (sig-assemble wrote the mass when a MATERIAL has rho > 0)
// and writes OUTDIR/case.hist (DS HIST, integrator/history_io.hpp) and OUTDIR/energy.csv. The
// contact strategies of ch. 3.3 / 8 are not marched yet: a deck with a CONTACT card is refused.
#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "integrator/history_io.hpp"
#include "integrator/march.hpp"
#include "integrator/time_card.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nopo.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

int main(int argc, char** argv) {
  return sig::run_stage("sig-march", [&] {
    // 1. Command line and cards: TIME, INITIAL, the linear backend of SOLVER.
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, "sig-march");
    const sig::Datafile datafile = sig::Datafile::read(args.datafile);
    const sig::Card* contact = datafile.find("CONTACT");
    const sig::TimeParameters time =
        sig::time_parameters(datafile.require("TIME"), contact != nullptr);
    if (contact != nullptr)
      contact->fail("", "sig-march marches elastodynamics without contact only; the dynamic "
                        "contact strategies (ch. 3.3 / 8) are not available yet");
    const sig::Card* solver_card = datafile.find("SOLVER");
    const std::string backend =
        solver_card ? solver_card->choice("linear", {"cholmod", "umfpack", "mumps"}, "cholmod")
                    : "cholmod";

    // 2. Mesh and assembled system; a dynamic case needs a mass.
    const sig::Mesh mesh = sig::read_nopo(args.ds_path("nopo"));
    const sig::LinearSystem system = sig::read_tae(args.ds_path("tae"));
    if (system.M.nonZeros() == 0)
      throw sig::InputError(datafile.path, 0, "rho",
                            "every MATERIAL has density 0: a dynamic case (TIME card) needs a "
                            "mass, give the MATERIAL cards rho > 0");

    // 3. Dirichlet elimination (constant imposed values, zero imposed velocity) and the initial
    //    state on the free dofs.
    const sig::ReducedSystem reduced = sig::reduce(system);
    const sig::InitialFields initial_full = sig::initial_fields(datafile, mesh);
    sig::DynamicState initial;
    initial.time = 0.0;
    initial.u = reduced.restrict(initial_full.u);
    initial.v = reduced.restrict(initial_full.v);

    // 4. The scheme: its step operator K + (4 / k^2) M is factorized here, once.
    sig::Stopwatch clock;
    auto scheme = sig::make_time_scheme(
        time.scheme,
        sig::reduced_elastodynamics(reduced, sig::mass_matrix(system, time.mass, mesh)), time.k,
        backend);

    // 5. March, with a progress line: step / steps, time, total energy.
    sig::Progress progress("sig-march " + time.scheme, time.steps);
    char detail[96];
    const auto observer = [&](const sig::DynamicState& state, const sig::EnergyRecord& energy) {
      std::snprintf(detail, sizeof detail, "t = %.6g  E = %.12g", state.time, energy.total);
      progress.update(energy.step, detail);
    };
    const sig::MarchHistory history =
        sig::march(*scheme, initial, time.steps, time.output_every, observer);
    progress.finish(detail);
    const double seconds = clock.seconds();

    // 6. Write case.hist and energy.csv (both atomic) and report the energy drift.
    sig::write_hist(args.ds_path("hist"), history, reduced, time, backend, seconds,
                    datafile.title());
    const auto csv_path = args.outdir / "energy.csv";
    sig::write_file_atomically(csv_path, sig::energy_csv(history.energy));
    const double e0 = history.energy.front().total;
    double drift = 0.0;
    for (const sig::EnergyRecord& r : history.energy)
      drift = std::max(drift, std::abs(r.total - r.external_work - e0));
    std::printf("sig-march: %s, mass %s (%s), %d free dofs, %d steps of k = %g, %zu states kept, "
                "E0 = %.12g, max |E - W - E0| = %.3g, %.3f s\n",
                time.scheme.c_str(), sig::to_string(time.mass).c_str(), backend.c_str(),
                reduced.num_free(), time.steps, time.k, history.outputs.size(), e0, drift, seconds);
    std::cout << args.ds_path("hist").string() << "\n" << csv_path.string() << "\n";
  });
}
