#include "material/mili.hpp"

#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/ranges.hpp"
#include "material/ciarlet_geymonat.hpp"
#include "material/saint_venant_kirchhoff.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_card.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <sstream>

namespace sig {

namespace {

// Codes of the MILI arrays `law` and `plane`.
constexpr std::int64_t law_hooke = 1;
constexpr std::int64_t law_svk = 2;
constexpr std::int64_t law_ciarlet_geymonat = 3;
constexpr std::int64_t law_kelvin_voigt = 4;
constexpr std::int64_t plane_strain_code = 1;
constexpr std::int64_t plane_stress_code = 2;

std::string joined(const std::vector<int>& numbers) {
  std::ostringstream out;
  for (std::size_t i = 0; i < numbers.size(); ++i)
    out << (i ? " " : "") << numbers[i];
  return out.str();
}

std::int64_t law_code(const SubdomainMaterial& m) {
  if (m.kelvin_voigt) return law_kelvin_voigt;
  if (!m.hyperelastic) return law_hooke;
  if (dynamic_cast<const CiarletGeymonat*>(m.hyperelastic.get())) return law_ciarlet_geymonat;
  return law_svk;
}

// A field of another law's parameter set is a mistake in the deck, not something to ignore.
void reject_fields(const Card& card, std::initializer_list<const char*> fields,
                   const std::string& law) {
  for (const char* field : fields)
    if (card.has(field))
      card.fail(field, "law=" + law + " takes no field '" + field +
                           "' (hooke, svk: E, nu; ciarlet-geymonat: c1, c2, a; kelvin-voigt: E, "
                           "nu, eta1, eta2)");
}

// The Ciarlet-Geymonat law of a card; Hooke's law then is its small-strain limit.
std::shared_ptr<const CiarletGeymonat> ciarlet_geymonat_from_card(const Card& card) {
  // c1 > 0, c2 >= 0, a >= 0: the card's ranges (core/ranges.hpp), checked by Card::real.
  const double c1 = card.real("c1"), c2 = card.real("c2"), a = card.real("a");
  return std::make_shared<const CiarletGeymonat>(c1, c2, a, plane_mode_from_card(card));
}

// The entry of `subdomain` in `table`, or null.
SubdomainMaterial* entry_of(MaterialTable& table, std::int64_t subdomain) {
  const auto it =
      std::find_if(table.entries.begin(), table.entries.end(),
                   [&](const SubdomainMaterial& m) { return m.subdomain == subdomain; });
  return it == table.entries.end() ? nullptr : &*it;
}

// The memory arrays of a MILI (none in files written before the viscoelastic law).
void read_memory_terms(const Ds& ds, const std::filesystem::path& path, MaterialTable& table) {
  if (!ds.has("memory_subdomain")) return;
  const auto subdomain = ds.ints("memory_subdomain");
  const auto young = ds.reals("memory_young");
  const auto poisson = ds.reals("memory_poisson");
  const auto beta = ds.reals("memory_beta");
  SIG_VERIFY(young.size() == subdomain.size() && poisson.size() == subdomain.size() &&
                 beta.size() == subdomain.size(),
             path.string() << ": the memory arrays of the MILI have different lengths");
  for (std::size_t i = 0; i < subdomain.size(); ++i) {
    SubdomainMaterial* m = entry_of(table, subdomain[i]);
    SIG_VERIFY(m != nullptr && m->kelvin_voigt,
               path.string() << ": array 'memory_subdomain' row " << i + 1 << ": sub-domain "
                             << subdomain[i] << " has no kelvin-voigt law");
    SIG_VERIFY(beta[i] > 0 && young[i] > 0 && poisson[i] > -1 && poisson[i] < 0.5,
               path.string() << ": memory term " << i + 1 << ": E = " << young[i] << ", nu = "
                             << poisson[i] << ", beta = " << beta[i] << " out of range");
    m->kelvin_voigt->memory.push_back({Hooke{young[i], poisson[i], m->hooke.plane}, beta[i]});
  }
}

// Each MEMORY card adds its term to the Kelvin-Voigt law of every sub-domain of its region.
void add_memory_terms(const Datafile& datafile, const Mesh& mesh, MaterialTable& table) {
  for (const Card* card : datafile.all("MEMORY"))
    for (int subdomain : card_regions(*card, mesh)) {
      SubdomainMaterial& m = *entry_of(table, subdomain); // card_regions: in the mesh
      if (!m.kelvin_voigt) {
        std::ostringstream what;
        what << "sub-domain " << subdomain << " is not law=kelvin-voigt: a memory term belongs to "
             << "a viscoelastic law";
        card->fail("region", what.str());
      }
      m.kelvin_voigt->memory.push_back(memory_term_from_card(*card, m.hooke.plane));
    }
}

} // namespace

const SubdomainMaterial& MaterialTable::of(int subdomain) const {
  const auto it =
      std::lower_bound(entries.begin(), entries.end(), subdomain,
                       [](const SubdomainMaterial& m, int number) { return m.subdomain < number; });
  SIG_VERIFY(it != entries.end() && it->subdomain == subdomain,
             "no material law for sub-domain " << subdomain);
  return *it;
}

bool MaterialTable::has_mass() const {
  return std::any_of(entries.begin(), entries.end(),
                     [](const SubdomainMaterial& m) { return m.density > 0.0; });
}

bool MaterialTable::has_viscosity() const {
  return std::any_of(entries.begin(), entries.end(),
                     [](const SubdomainMaterial& m) { return m.kelvin_voigt.has_value(); });
}

std::vector<std::pair<int, MemoryTerm>> MaterialTable::memory_terms() const {
  std::vector<std::pair<int, MemoryTerm>> terms;
  for (const SubdomainMaterial& m : entries)
    if (m.kelvin_voigt)
      for (const MemoryTerm& term : m.kelvin_voigt->memory)
        terms.emplace_back(m.subdomain, term);
  return terms;
}

SubdomainMaterial material_from_card(const Card& card) {
  const std::string law = card.choice("law", {"hooke", "svk", "ciarlet-geymonat", "kelvin-voigt"});
  SubdomainMaterial material;
  if (law != "kelvin-voigt") reject_fields(card, {"eta1", "eta2"}, law);
  if (law == "ciarlet-geymonat") {
    reject_fields(card, {"E", "nu"}, law);
    const auto cg = ciarlet_geymonat_from_card(card);
    material.hooke = cg->linearized();
    material.hyperelastic = cg;
  } else {
    reject_fields(card, {"c1", "c2", "a"}, law);
    material.hooke = hooke_from_card(card);
    if (law == "svk")
      material.hyperelastic = std::make_shared<const SaintVenantKirchhoff>(
          material.hooke.E, material.hooke.nu, material.hooke.plane);
    if (law == "kelvin-voigt") material.kelvin_voigt = KelvinVoigt{viscosity_from_card(card), {}};
  }
  material.thickness = card.real("thickness"); // > 0 and rho >= 0: core/ranges.hpp
  material.density = card.real("rho");
  return material;
}

namespace {

// A 3D body has no plane mode and no thickness (its laws, Hooke's, Kelvin-Voigt's and the
// hyperelastic ones, are written on the 3D tensors): a 2D field in a 3D deck is refused on its
// card, not silently dropped.
void verify_card_in_3d(const Card& card) {
  for (const char* field : {"plane", "thickness"})
    if (card.has(field))
      card.fail(field, std::string("the mesh is 3D: '") + field +
                           "' belongs to a 2D body (plane strain or stress, a plate's thickness)");
}

} // namespace

MaterialTable material_table_from_cards(const Datafile& datafile, const Mesh& mesh) {
  const std::vector<int> present = mesh.subdomains();
  const std::vector<const Card*> cards = datafile.all("MATERIAL");
  if (mesh.dim == 3) {
    for (const Card* card : cards)
      verify_card_in_3d(*card);
  }
  if (cards.empty())
    throw InputError(datafile.path, 0, "",
                     "no MATERIAL card (sub-domains of the mesh: " + joined(present) + ")");

  std::map<int, const Card*> assigned_by;
  MaterialTable table;
  for (const Card* card : cards) {
    const SubdomainMaterial law = material_from_card(*card);
    const std::vector<int> targets = card_regions(*card, mesh);
    for (int subdomain : targets) {
      const auto [it, inserted] = assigned_by.emplace(subdomain, card);
      if (!inserted) {
        std::ostringstream what;
        what << "sub-domain " << subdomain << " already has a law (MATERIAL card on line "
             << it->second->line << ")";
        card->fail("region", what.str());
      }
      SubdomainMaterial entry = law;
      entry.subdomain = subdomain;
      table.entries.push_back(entry);
    }
  }
  for (int subdomain : present) {
    if (!assigned_by.count(subdomain)) {
      std::ostringstream what;
      what << "sub-domain " << subdomain
           << " of the mesh has no MATERIAL card (sub-domains: " << joined(present) << ")";
      cards.back()->fail("region", what.str());
    }
  }
  std::sort(table.entries.begin(), table.entries.end(),
            [](const SubdomainMaterial& a, const SubdomainMaterial& b) {
              return a.subdomain < b.subdomain;
            });
  add_memory_terms(datafile, mesh, table);
  return table;
}

void write_mili(const std::filesystem::path& path, const MaterialTable& table,
                const std::string& title) {
  std::vector<std::int64_t> subdomain, law, plane;
  std::vector<double> young, poisson, thickness, density, c1, c2, a, eta1, eta2;
  std::vector<std::int64_t> memory_subdomain;
  std::vector<double> memory_young, memory_poisson, memory_beta;
  for (const SubdomainMaterial& m : table.entries) {
    eta1.push_back(m.kelvin_voigt ? m.kelvin_voigt->viscosity.eta1 : 0.0);
    eta2.push_back(m.kelvin_voigt ? m.kelvin_voigt->viscosity.eta2 : 0.0);
    subdomain.push_back(m.subdomain);
    law.push_back(law_code(m));
    const auto* cg = dynamic_cast<const CiarletGeymonat*>(m.hyperelastic.get());
    c1.push_back(cg ? cg->c1() : 0.0);
    c2.push_back(cg ? cg->c2() : 0.0);
    a.push_back(cg ? cg->a() : 0.0);
    plane.push_back(m.hooke.plane == PlaneMode::strain ? plane_strain_code : plane_stress_code);
    young.push_back(m.hooke.E);
    poisson.push_back(m.hooke.nu);
    thickness.push_back(m.thickness);
    density.push_back(m.density);
  }
  for (const auto& [subdomain, term] : table.memory_terms()) {
    memory_subdomain.push_back(subdomain);
    memory_young.push_back(term.modulus.E);
    memory_poisson.push_back(term.modulus.nu);
    memory_beta.push_back(term.beta);
  }
  Ds ds("MILI", title, "sig-material");
  ds.put("subdomain", subdomain);
  ds.put("law", law);
  ds.put("young", young);
  ds.put("poisson", poisson);
  ds.put("plane", plane);
  ds.put("thickness", thickness);
  ds.put("density", density);
  ds.put("c1", c1);
  ds.put("c2", c2);
  ds.put("a", a);
  ds.put("eta1", eta1);
  ds.put("eta2", eta2);
  ds.put("memory_subdomain", memory_subdomain);
  ds.put("memory_young", memory_young);
  ds.put("memory_poisson", memory_poisson);
  ds.put("memory_beta", memory_beta);
  write_ds(path, ds);
}

MaterialTable read_mili(const std::filesystem::path& path) {
  const Ds ds = read_ds(path, "MILI");
  const auto subdomain = ds.ints("subdomain");
  const auto law = ds.ints("law");
  const auto plane = ds.ints("plane");
  const auto young = ds.reals("young");
  const auto poisson = ds.reals("poisson");
  const auto thickness = ds.reals("thickness");
  const auto density = ds.reals("density");
  const std::size_t n = subdomain.size();
  // MILI files written before the hyperelastic laws have no c1, c2, a.
  const auto optional = [&](const char* name) {
    return ds.has(name) ? ds.reals(name) : std::vector<double>(n, 0.0);
  };
  const auto c1 = optional("c1");
  const auto c2 = optional("c2");
  const auto a = optional("a");
  const auto eta1 = optional("eta1");
  const auto eta2 = optional("eta2");
  SIG_VERIFY(law.size() == n && plane.size() == n && young.size() == n && poisson.size() == n &&
                 thickness.size() == n && density.size() == n && c1.size() == n && c2.size() == n &&
                 a.size() == n && eta1.size() == n && eta2.size() == n,
             path.string() << ": MILI arrays have different lengths");
  MaterialTable table;
  for (std::size_t i = 0; i < n; ++i) {
    SIG_VERIFY(law[i] >= law_hooke && law[i] <= law_kelvin_voigt,
               path.string() << ": array 'law' row " << i + 1 << ": unknown law code " << law[i]);
    SIG_VERIFY(plane[i] == plane_strain_code || plane[i] == plane_stress_code,
               path.string() << ": array 'plane' row " << i + 1 << ": unknown code " << plane[i]);
    SIG_VERIFY(i == 0 || subdomain[i] > subdomain[i - 1],
               path.string() << ": array 'subdomain' is not strictly increasing at row " << i + 1);
    // The ranges of the MATERIAL card hold for the file too (core/ranges.hpp).
    const std::string file = path.string();
    verify_in_range(static_cast<double>(subdomain[i]), "MATERIAL", "region", file, "subdomain",
                    i + 1);
    if (law[i] == law_ciarlet_geymonat) {
      verify_in_range(c1[i], "MATERIAL", "c1", file, "c1", i + 1);
      verify_in_range(c2[i], "MATERIAL", "c2", file, "c2", i + 1);
      verify_in_range(a[i], "MATERIAL", "a", file, "a", i + 1);
    } else {
      verify_in_range(young[i], "MATERIAL", "E", file, "young", i + 1);
      verify_in_range(poisson[i], "MATERIAL", "nu", file, "poisson", i + 1);
    }
    verify_in_range(thickness[i], "MATERIAL", "thickness", file, "thickness", i + 1);
    verify_in_range(density[i], "MATERIAL", "rho", file, "density", i + 1);
    SubdomainMaterial m;
    m.subdomain = static_cast<int>(subdomain[i]);
    m.hooke.E = young[i];
    m.hooke.nu = poisson[i];
    m.hooke.plane = plane[i] == plane_strain_code ? PlaneMode::strain : PlaneMode::stress;
    if (law[i] == law_svk) {
      m.hyperelastic =
          std::make_shared<const SaintVenantKirchhoff>(m.hooke.E, m.hooke.nu, m.hooke.plane);
    } else if (law[i] == law_ciarlet_geymonat) {
      SIG_VERIFY(ds.has("c1") && ds.has("c2") && ds.has("a"),
                 path.string() << ": row " << i + 1
                               << " is a ciarlet-geymonat law but c1, c2, a are missing");
      const auto cg = std::make_shared<const CiarletGeymonat>(c1[i], c2[i], a[i], m.hooke.plane);
      m.hooke = cg->linearized();
      m.hyperelastic = cg;
    } else if (law[i] == law_kelvin_voigt) {
      SIG_VERIFY(eta1[i] >= 0 && eta2[i] >= 0,
                 path.string() << ": row " << i + 1 << ": negative viscosity eta1 = " << eta1[i]
                               << ", eta2 = " << eta2[i]);
      m.kelvin_voigt = KelvinVoigt{{eta1[i], eta2[i]}, {}};
    }
    m.thickness = thickness[i];
    m.density = density[i];
    table.entries.push_back(m);
  }
  read_memory_terms(ds, path, table);
  return table;
}

} // namespace sig
