#pragma once
// MILI, MODULEF's "physical properties of each medium": one constitutive law per sub-domain of
// the mesh, with the thickness of the 2D body (stiffness, mass and loads are per unit thickness
// times this) and the mass density.
//
// MATERIAL card: `MATERIAL law=hooke E=... nu=... [plane=strain|stress] [thickness=1] [rho=0]
// [region=1,2]`; without region= the card applies to every sub-domain. The hyperelastic laws
// (large deformation, material/hyperelastic.hpp) take the same plane, thickness, rho, region:
//   `law=svk E=... nu=...`                       Saint Venant-Kirchhoff (thesis 1.62)
//   `law=ciarlet-geymonat c1=... c2=... a=...`   the thesis's "Ogden" W (1.63)
// and the viscoelastic law of chapter 5 (material/kelvin_voigt.hpp), small strain:
//   `law=kelvin-voigt E=... nu=... eta1=... eta2=...` with repeatable `MEMORY [region=] E= nu=
//   beta=`
//
// DS "MILI", one row per sub-domain, sorted by sub-domain number:
//   subdomain (int64), law (int64: 1 = hooke, 2 = svk, 3 = ciarlet-geymonat, 4 = kelvin-voigt),
//   young, poisson (for ciarlet-geymonat those of its small-strain limit; for kelvin-voigt B's),
//   plane (int64: 1 strain, 2 stress), thickness, density, c1, c2, a (0 unless
//   ciarlet-geymonat), eta1, eta2 (0 unless kelvin-voigt); and one row per memory term:
//   memory_subdomain (int64), memory_young, memory_poisson, memory_beta. Files without the
//   arrays of a later law read as 0 or none.
#include "material/hooke.hpp"
#include "material/hyperelastic.hpp"
#include "material/kelvin_voigt.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sig {

class Card;
class Datafile;
struct Mesh;

/// The law of one sub-domain.
struct SubdomainMaterial {
  int subdomain = 1;
  /// Hooke's law; for a hyperelastic sub-domain, the small-strain limit of its law (the
  /// tangent at F = I), so that the linear(ized) assembly and post-processing still apply.
  Hooke hooke;
  /// The large-deformation law of law=svk | ciarlet-geymonat; null for law=hooke.
  std::shared_ptr<const HyperelasticLaw> hyperelastic;
  /// Viscosity and memory of law=kelvin-voigt (hooke is then its elastic part B); empty otherwise.
  std::optional<KelvinVoigt> kelvin_voigt;
  double thickness = 1.0; ///< > 0
  double density = 0.0;   ///< rho >= 0
};

struct MaterialTable {
  std::vector<SubdomainMaterial> entries; ///< sorted by sub-domain, one per sub-domain

  /// The law of sub-domain `subdomain`; sig::Error if the table has none.
  const SubdomainMaterial& of(int subdomain) const;
  /// True if some sub-domain has a positive density (the problem has inertia).
  bool has_mass() const;
  /// True if some sub-domain is law=kelvin-voigt.
  bool has_viscosity() const;
  /// Every memory term of every sub-domain, with its sub-domain, in table order.
  std::vector<std::pair<int, MemoryTerm>> memory_terms() const;
};

/// Law, thickness and density of one MATERIAL card (subdomain left at its default). Throws
/// sig::InputError naming the line and field for an unknown law, E <= 0, nu outside (-1, 1/2),
/// c1 <= 0, c2 < 0, a < 0, thickness <= 0 or rho < 0.
SubdomainMaterial material_from_card(const Card& card);

/// The table of every sub-domain of `mesh` from the MATERIAL cards. Each sub-domain must get
/// exactly one card: a sub-domain named twice, a region that is not in the mesh, or a sub-domain
/// left without a law is an InputError naming the card line. The MEMORY cards add their term to
/// each sub-domain of their region, which must be law=kelvin-voigt.
MaterialTable material_table_from_cards(const Datafile& datafile, const Mesh& mesh);

void write_mili(const std::filesystem::path& path, const MaterialTable& table,
                const std::string& title);
MaterialTable read_mili(const std::filesystem::path& path);

} // namespace sig
