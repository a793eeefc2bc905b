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
//
// DS "MILI", one row per sub-domain, sorted by sub-domain number:
//   subdomain (int64), law (int64: 1 = hooke, 2 = svk, 3 = ciarlet-geymonat), young, poisson
//   (for ciarlet-geymonat those of its small-strain limit), plane (int64: 1 strain, 2 stress),
//   thickness, density, c1, c2, a (0 unless ciarlet-geymonat; files without them read as 0).
#include "material/hooke.hpp"
#include "material/hyperelastic.hpp"

#include <filesystem>
#include <memory>
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
  double thickness = 1.0; ///< > 0
  double density = 0.0;   ///< rho >= 0
};

struct MaterialTable {
  std::vector<SubdomainMaterial> entries; ///< sorted by sub-domain, one per sub-domain

  /// The law of sub-domain `subdomain`; sig::Error if the table has none.
  const SubdomainMaterial& of(int subdomain) const;
  /// True if some sub-domain has a positive density (the problem has inertia).
  bool has_mass() const;
};

/// Law, thickness and density of one MATERIAL card (subdomain left at its default). Throws
/// sig::InputError naming the line and field for an unknown law, E <= 0, nu outside (-1, 1/2),
/// c1 <= 0, c2 < 0, a < 0, thickness <= 0 or rho < 0.
SubdomainMaterial material_from_card(const Card& card);

/// The table of every sub-domain of `mesh` from the MATERIAL cards. Each sub-domain must get
/// exactly one card: a sub-domain named twice, a region that is not in the mesh, or a sub-domain
/// left without a law is an InputError naming the card line.
MaterialTable material_table_from_cards(const Datafile& datafile, const Mesh& mesh);

void write_mili(const std::filesystem::path& path, const MaterialTable& table,
                const std::string& title);
MaterialTable read_mili(const std::filesystem::path& path);

} // namespace sig
