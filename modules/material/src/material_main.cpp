// sig-material DATAFILE [-o OUTDIR]: MODULEF's COMILI. Reads the MATERIAL cards and the mesh
// OUTDIR/case.nopo, gives every sub-domain its law and writes OUTDIR/case.mili.
#include "material/stage_main.hpp"

#include "core/datafile.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nopo.hpp"

#include <sstream>

namespace sig {

int material_main(int argc, char** argv) {
  const sig::StageHelp help{.name = "sig-material",
                            .purpose = "Material stage (MODULEF's COMILI): gives every sub-domain "
                                       "of the mesh its constitutive law "
                                       "from the MATERIAL cards, checked against the mesh.",
                            .reads = {"DATAFILE", "OUTDIR/case.nopo (sig-mesh)"},
                            .writes = {"OUTDIR/case.mili (law and parameters per sub-domain)"},
                            .cards = sig::stage_cards("material").cards};
  return sig::run_stage("sig-material", [&] {
    // 1. Command line and inputs.
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, help);
    const sig::Datafile& datafile = args.deck;
    const sig::Mesh mesh = sig::read_nopo(args.ds_path("nopo"));

    // 2. One law per sub-domain, checked against the mesh.
    const sig::MaterialTable table = sig::material_table_from_cards(datafile, mesh);

    // 3. Write the MILI and say what it holds.
    sig::write_mili(args.ds_path("mili"), table, datafile.title());
    for (const sig::SubdomainMaterial& m : table.entries) {
      std::ostringstream line;
      line << "sub-domain " << m.subdomain << ": "
           << (m.hyperelastic   ? m.hyperelastic->name() + " (small-strain limit"
               : m.kelvin_voigt ? std::string("kelvin-voigt (elastic part")
                                : std::string("hooke ("))
           << " E=" << m.hooke.E << " nu=" << m.hooke.nu << ") ";
      if (mesh.dim == 3)
        line << "3D";
      else
        line << "plane " << (m.hooke.plane == sig::PlaneMode::strain ? "strain" : "stress")
             << " thickness=" << m.thickness;
      line << " rho=" << m.density;
      if (m.kelvin_voigt) {
        line << " eta1=" << m.kelvin_voigt->viscosity.eta1
             << " eta2=" << m.kelvin_voigt->viscosity.eta2;
        for (const sig::MemoryTerm& term : m.kelvin_voigt->memory)
          line << ", memory exp(-" << term.beta << " t) (E=" << term.modulus.E
               << " nu=" << term.modulus.nu << ")";
      }
      sig::log_info(line.str());
    }
    sig::log_info("wrote " + args.ds_path("mili").string());
  });
}

} // namespace sig
