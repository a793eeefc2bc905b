// sig-post: the solved static case (or the marched dynamic one) for ParaView, tables and charts.
//
//   sig-post DATAFILE [-o OUTDIR]
//
// Reads OUTDIR/case.nopo, case.mili, case.b (+ case.cont when the datafile has a CONTACT card,
// and the time_* scalars of case.tae when it exists) and writes
//   OUTDIR/<stem>.pvd + <stem>_0000.vtu   unless the OUTPUT card says vtk=no (stem: OUTPUT
//                                          name=, default the datafile's stem)
//   OUTDIR/summary.json                    method, convergence, sizes, histories, times
//   OUTDIR/contact.csv                     one row per contact element (contact cases)
// A load-stepped case (finite strain: case.b holds step_u, stages/finite_strain_stage.hpp) writes
// <stem>.pvd with one <stem>_NNNN.vtu per converged load step, time = load factor, instead of
// the single state; summary.json and contact.csv are those of the final state as above.
// A dynamic case (TIME card) reads case.hist instead of case.b and writes <stem>.pvd with one
// <stem>_NNNN.vtu per state kept by sig-march (displacement, velocity, stress) and a summary.json
// of how it ran (title, scheme, ranks, ordering).
// A solution holding NaN or inf is refused (Ds::reals), and so is a field that overflows on its
// way to the .vtu (the VTK writer checks every field): a picture of garbage helps nobody.
#include "post/stage_mains.hpp"

#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "material/mili.hpp"
#include "mesh/nopo.hpp"
#include "post/contact_table.hpp"
#include "post/history_vtk.hpp"
#include "post/load_step_vtk.hpp"
#include "post/result_checks.hpp"
#include "post/solution_fields.hpp"
#include "post/stress.hpp"
#include "post/summary.hpp"
#include "post/vtk_writer.hpp"

#include <filesystem>
#include <iostream>
#include <optional>

namespace {

/// COMPARE analytic=hertz R= f= [x0=]: the pressure on Gamma3 against thesis (7.38), with the
/// elastic constants of the (single) Hooke material.
sig::Json hertz_comparison(const sig::Card& compare, const sig::MaterialTable& materials,
                           const std::vector<sig::ContactRow>& contact) {
  compare.choice("analytic", {"hertz"});
  if (contact.empty()) compare.fail("analytic", "a Hertz comparison needs a CONTACT card");
  if (contact.front().dim == 3)
    compare.fail("analytic", "analytic=hertz is the 2D cylinder's (thesis 7.4.1); a 3D ball is "
                             "compared with Hertz by drivers/scene3d_hertz.sh's report");
  if (materials.entries.size() != 1)
    compare.fail("analytic", "a Hertz comparison needs a single material");
  sig::HertzData data;
  data.radius = compare.real("R");
  data.traction = compare.real("f");
  data.young = materials.entries.front().hooke.E;
  data.poisson = materials.entries.front().hooke.nu;
  if (data.radius <= 0) compare.fail("R", "must be positive");
  if (data.traction <= 0) compare.fail("f", "must be positive");
  const auto samples = sig::pressure_samples(contact, compare.real("x0"));
  return sig::hertz_json(data, sig::hertz_pressure_error(data, samples));
}

// Prints the files sig-post wrote, then records them in case.post with what they were made from
// (core/provenance.hpp): the inputs and cards that drivers/chain.sh compares with the deck to know
// whether the outputs are up to date. Written last: a sig-post stopped before the end leaves the
// record of its previous run, which matches the case only if that run had the same inputs.
void record_outputs(const sig::StageArgs& args, const sig::Datafile& datafile,
                    const std::vector<std::filesystem::path>& written) {
  std::string names;
  for (const auto& file : written) {
    std::cout << file.string() << "\n";
    names += file.filename().string() + "\n";
  }
  sig::Ds record("POST", datafile.title(), "sig-post");
  record.put_text("files", names);
  sig::write_ds(args.ds_path("post"), record);
}

} // namespace

namespace sig {

int post_main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-post",
      .purpose = "Post-processing: the solved case (or the marched one, with a TIME card) for "
                 "ParaView and scripts. Refuses a solution holding NaN or inf.",
      .reads = {"DATAFILE", "OUTDIR/case.nopo, case.mili",
                "OUTDIR/case.b (sig-solve) or, with a TIME card, OUTDIR/case.hist (sig-march)",
                "OUTDIR/case.cont (with a CONTACT card)"},
      .writes = {"OUTDIR/<name>.pvd and <name>_NNNN.vtu (unless OUTPUT vtk=no; one .vtu per load "
                 "step or kept time step)",
                 "OUTDIR/summary.json (method, convergence, sizes, histories, times, energies, "
                 "Hertz comparison; of a march: its scheme, ranks and ordering)",
                 "OUTDIR/contact.csv (one row per contact node; contact cases)",
                 "OUTDIR/case.post (the files above and what they were made from: the inputs "
                 "and the deck's cards, for drivers/chain.sh)"},
      .cards = sig::stage_cards("post").cards};
  return sig::run_stage("sig-post", [&] {
    // 1. Command line, datafile and the OUTPUT card.
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, help);
    const sig::Datafile& datafile = args.deck;
    const sig::Card* output = datafile.find("OUTPUT");
    const bool write_vtk = output == nullptr || output->choice("vtk", {"yes", "no"}) == "yes";
    const std::string compressor =
        output ? output->choice("compression", {"zlib", "lz4", "none"}, "zlib") : "zlib";
    const sig::VtkCompression compression = compressor == "lz4"    ? sig::VtkCompression::lz4
                                            : compressor == "none" ? sig::VtkCompression::none
                                                                   : sig::VtkCompression::zlib;

    // 2. Mesh and materials. A dynamic case (TIME card) is shown as the states sig-march kept
    //    in case.hist, one .vtu each; its energies are in energy.csv already.
    const sig::Mesh mesh = sig::read_nopo(args.ds_path("nopo"));
    const sig::MaterialTable materials = sig::read_mili(args.ds_path("mili"));
    const std::string stem = output ? output->file_name("name", datafile.stem()) : datafile.stem();
    std::vector<std::filesystem::path> written;
    if (datafile.find("TIME") != nullptr) {
      const sig::Ds hist = sig::read_ds(args.ds_path("hist"), "HIST");
      sig::verify_history_ds(hist, mesh);
      if (write_vtk)
        for (const auto& file : sig::write_history_vtk(
                 args.outdir, stem, mesh, materials, hist,
                 {{"title", datafile.title()}, {"scheme", hist.text("scheme")}}, compression))
          written.push_back(file);
      // How the march ran, where a user looks (its numbers are in energy.csv and case.hist).
      sig::Json summary = sig::Json::object();
      summary.set("title", datafile.title());
      summary.set("scheme", hist.text("scheme"));
      summary.set("ranks", hist.has("ranks") ? static_cast<long>(hist.integer("ranks")) : 1L);
      summary.set("ordering", hist.has("ordering") ? hist.text("ordering") : std::string());
      const auto summary_path = args.outdir / "summary.json";
      sig::write_file_atomically(summary_path, summary.dump() + "\n");
      written.push_back(summary_path);
      record_outputs(args, datafile, written);
      return;
    }

    // 3. The static solution.
    const auto b_path = args.ds_path("b");
    const sig::Ds solution = sig::read_ds(b_path, "B");
    sig::verify_solution_ds(solution, mesh);
    const std::vector<double> u = solution.reals("u"); // of the mesh's size: checked above

    // 4. Contact elements joined with their final state (contact cases only).
    std::vector<sig::ContactRow> contact;
    sig::Ds cont;
    const bool contact_case = datafile.find("CONTACT") != nullptr;
    if (contact_case) {
      cont = sig::read_ds(args.ds_path("cont"), "CONT");
      contact = sig::contact_rows(mesh, cont, solution);
    }

    // 5. ParaView: one .vtu per load step of a large-deformation solve, else one .vtu (time 0),
    //    and the .pvd collection.
    if (write_vtk && sig::has_load_step_states(solution)) {
      const sig::VtkText data{{"title", datafile.title()}, {"method", solution.text("method")}};
      for (const auto& file :
           sig::write_load_step_vtk(args.outdir, stem, mesh, materials, solution,
                                    contact_case ? &cont : nullptr, data, compression))
        written.push_back(file);
    } else if (write_vtk) {
      const sig::SolutionFields fields = sig::solution_fields(mesh, u, materials, contact);
      const std::string vtu = stem + "_0000.vtu";
      const bool converged = solution.integer("converged") != 0;
      sig::write_vtu(
          args.outdir / vtu, mesh, fields.point, fields.cell,
          {{"title", datafile.title()},
           {"method", solution.text("method")},
           {"convergence",
            converged ? "converged" : "NOT converged (Nv): " + solution.text("failure")}},
          {{"converged", converged ? 1.0 : 0.0}}, compression);
      sig::write_pvd(args.outdir / (stem + ".pvd"), {{0.0, vtu}});
      written.push_back(args.outdir / (stem + ".pvd"));
      written.push_back(args.outdir / vtu);
    }

    // 6. summary.json with the times of every stage that recorded some.
    // Of case.tae (hundreds of MB at scale) the loads and the phase times only.
    std::optional<sig::Ds> tae;
    if (std::filesystem::exists(args.ds_path("tae")))
      tae = sig::read_ds(args.ds_path("tae"), "TAE", [](const std::string& name) {
        return name == "f" || name.starts_with("time_");
      });
    const auto times =
        sig::gather_times({tae ? &*tae : nullptr, contact_case ? &cont : nullptr, &solution});
    sig::Json summary = sig::build_summary(datafile.title(), mesh, solution, contact, times);
    // Total potential energy W - f.u: its differences between meshes measure the energy-norm
    // error.
    if (tae) {
      const std::vector<double> load = tae->reals("f");
      double work = 0;
      SIG_VERIFY(load.size() == u.size(), args.ds_path("tae").string()
                                              << ": array 'f' holds " << load.size()
                                              << " values, case.b's 'u' " << u.size());
      for (std::size_t i = 0; i < load.size(); ++i)
        work += load[i] * u[i];
      const double strain = mesh.dim == 3 ? sig::strain_energy_3d(mesh, u, materials)
                                          : sig::strain_energy(mesh, u, materials);
      summary.set("energy",
                  sig::Json(sig::Json::Object{
                      {"strain", strain}, {"external_work", work}, {"potential", strain - work}}));
    }
    if (const sig::Card* compare = datafile.find("COMPARE"))
      summary.set("hertz", hertz_comparison(*compare, materials, contact));
    const auto summary_path = args.outdir / "summary.json";
    sig::write_file_atomically(summary_path, summary.dump() + "\n");
    written.push_back(summary_path);

    // 7. contact.csv; a stale one from an earlier contact variant would mislead, so remove it.
    const auto csv_path = args.outdir / "contact.csv";
    if (contact_case) {
      sig::write_file_atomically(csv_path,
                                 sig::contact_csv(contact, solution.integer("converged") != 0));
      written.push_back(csv_path);
    } else {
      std::filesystem::remove(csv_path);
    }
    record_outputs(args, datafile, written);
  });
}

} // namespace sig
