// sig-march DATAFILE [-o OUTDIR]: elastodynamics, M a + K u = f, marched from the INITIAL state
// with the scheme of the TIME card, with or without node-to-rigid contact; or, with TIME
// scheme=quasistatic, the quasistatic viscoelastic march in velocity of ch. 5
// (integrator/quasistatic_stage.hpp).
//
//   TIME scheme=midpoint|newmark T= k= [output_every=1] [mass=consistent|lumped|emm]
//   INITIAL [u=ux,uy] [v=vx,vy] [region=...]
//   CONTACT ... [strategy=signorini|compliance|specific-penalty|two-step|ipm] [r=] [gap=]
//   SOLVER linear=cholmod|umfpack|mumps maxit=   (K + (4 / k^2) M factorized once; maxit: the
//          strategy's Newton iterations per phase, default 50)
//
// Reads OUTDIR/case.nopo and case.tae (sig-assemble wrote the mass when a MATERIAL has rho > 0),
// with a CONTACT card also case.cont (sig-contact), and writes OUTDIR/case.hist (DS HIST,
// integrator/history_io.hpp) and OUTDIR/energy.csv. The contact strategies are those of
// integrator/contact_strategy.hpp (default signorini); r is the foundation stiffness per unit
// area, g (old spelling gap) the depth of the unilateral bound's wall (for ipm: the allowed
// penetration). A step whose Newton fails stops the march: the files hold the steps done, HIST
// converged = 0, a warning is printed and the stage exits 0.
#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "integrator/contact_card.hpp"
#include "integrator/contact_march.hpp"
#include "integrator/contact_strategy.hpp"
#include "integrator/dynamic_stage.hpp"
#include "integrator/history_io.hpp"
#include "integrator/march.hpp"
#include "integrator/quasistatic_stage.hpp"
#include "integrator/time_card.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nopo.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

int main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-march",
      .purpose = "Time marching of elastodynamics, M a + K u = f, from the INITIAL state with the "
                 "scheme of the TIME card (K + (4/k^2) M factorized once), with node-to-rigid "
                 "contact by the CONTACT card's strategy; or (scheme=quasistatic) the quasistatic "
                 "Kelvin-Voigt march in velocity of ch. 5 with contact laws in velocity, its step "
                 "matrix factorized and condensed once (case.hist, steps.csv); or "
                 "(scheme=backward-euler) the viscoelastodynamic march in velocity of ch. 6, "
                 "(M/k + C + k K) factorized and condensed once, contact laws of the displacement "
                 "and friction of the slip rate, with the convexification loop in every step for "
                 "FRICTION law=nonmonotone. A step whose Newton "
                 "fails stops the "
                 "march: the files hold the steps done, a warning is printed and the stage exits "
                 "0. A progress line shows the step, time steps per second and the time left.",
      .reads = {"DATAFILE", "OUTDIR/case.nopo (sig-mesh)",
                "OUTDIR/case.tae (sig-assemble; a MATERIAL with rho > 0 gives the mass)",
                "OUTDIR/case.cont (sig-contact; with a CONTACT card)"},
      .writes = {"OUTDIR/case.hist (kept states, energies, contact pressures)",
                 "OUTDIR/energy.csv (one row per step: energies, contact work, penetration, active "
                 "nodes, Newton iterations)"},
      .cards = {"TITLE", "TIME", "INITIAL", "CONTACT", "FRICTION", "SOLVER", "MATERIAL", "MEMORY",
                "CONVEXIFICATION"}};
  return sig::run_stage("sig-march", [&] {
    // 1. Command line and cards: TIME, INITIAL, CONTACT (strategy, r, gap), SOLVER (backend,
    // maxit).
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, help);
    const sig::Datafile datafile = sig::Datafile::read(args.datafile);
    const sig::Card* contact = datafile.find("CONTACT");
    const sig::TimeParameters time =
        sig::time_parameters(datafile.require("TIME"), contact != nullptr);
    if (time.scheme == "quasistatic") {
      sig::run_quasistatic_march(args, datafile, time);
      return;
    }
    if (time.scheme == "backward-euler") {
      sig::run_backward_euler_march(args, datafile, time);
      return;
    }
    const sig::Card* solver_card = datafile.find("SOLVER");
    const std::string backend =
        solver_card ? solver_card->choice("linear", {"cholmod", "umfpack", "mumps"}, "cholmod")
                    : "cholmod";
    sig::ContactHistoryInfo contact_info;
    sig::ContactStrategyParameters strategy_parameters;
    if (const sig::Card* friction = sig::friction_card_with_law(datafile))
      friction->fail("law", "friction in time marching is not implemented yet: a TIME deck is "
                            "frictionless (law=none, or no FRICTION card)");
    if (contact != nullptr) {
      contact_info = sig::contact_history_info(*contact);
      strategy_parameters = sig::contact_strategy_parameters(*contact, solver_card);
    }

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

    // 4. The contact boundary of case.cont, and the scheme: its step operator K + (4 / k^2) M
    //    (EMM included) is factorized here, once.
    std::optional<sig::ContactElements> elements;
    if (contact != nullptr) elements = sig::read_cont(args.ds_path("cont"));
    const sig::ContactNormals normals =
        elements ? sig::contact_normals(*elements) : sig::ContactNormals{};
    sig::Stopwatch clock;
    auto scheme = sig::make_time_scheme(
        time.scheme,
        sig::reduced_elastodynamics(reduced, sig::mass_matrix(system, time.mass, mesh, normals)),
        time.k, backend);

    // 5. March, with a progress line: step / steps, time, total energy.
    const std::string label =
        time.scheme + (contact != nullptr ? " + " + contact_info.strategy : std::string());
    sig::Progress progress("sig-march " + label, time.steps, "time steps");
    char detail[96];
    const auto observer = [&](const sig::DynamicState& state, const sig::EnergyRecord& energy) {
      std::snprintf(detail, sizeof detail, "t = %.6g  E = %.12g", state.time, energy.total);
      progress.update(energy.step, detail);
    };
    sig::MarchHistory history;
    if (elements) {
      const sig::ContactBoundary boundary = sig::contact_boundary(*elements, mesh, reduced);
      contact_info.nodes = boundary.nodes;
      const auto strategy = sig::make_contact_strategy(contact_info.strategy, strategy_parameters);
      history = sig::march_with_contact(*scheme, boundary, *strategy, initial, time.steps,
                                        time.output_every, observer);
    } else {
      history = sig::march(*scheme, initial, time.steps, time.output_every, observer);
    }
    const double seconds = clock.seconds();
    if (history.converged) {
      progress.finish(detail);
    } else {
      progress.finish(std::string(detail) + "  STOPPED after step " +
                      std::to_string(history.energy.size() - 1));
      sig::log_warning("sig-march stopped: " + history.failure);
    }

    // 6. Write case.hist and energy.csv (both atomic) and report the energy drift.
    sig::write_hist(args.ds_path("hist"), history, reduced, time, backend, seconds,
                    datafile.title(), elements ? &contact_info : nullptr);
    const auto csv_path = args.outdir / "energy.csv";
    sig::write_file_atomically(csv_path, sig::energy_csv(history.energy));
    const double e0 = history.energy.front().total;
    double drift = 0.0;
    for (const sig::EnergyRecord& r : history.energy)
      drift = std::max(drift, std::abs(r.total - r.external_work - r.contact_work - e0));
    double penetration = 0.0;
    for (const sig::EnergyRecord& r : history.energy)
      penetration = std::max(penetration, r.max_penetration);
    std::printf("sig-march: %s, mass %s (%s), %d free dofs, %zu/%d steps of k = %g, %zu states "
                "kept, E0 = %.12g, max |E - W - Wc - E0| = %.3g, max penetration %.6g, %.3f s%s\n",
                label.c_str(), sig::to_string(time.mass).c_str(), backend.c_str(),
                reduced.num_free(), history.energy.size() - 1, time.steps, time.k,
                history.outputs.size(), e0, drift, penetration, seconds,
                history.converged ? "" : " (STOPPED: Newton failed)");
    std::cout << args.ds_path("hist").string() << "\n" << csv_path.string() << "\n";
  });
}
