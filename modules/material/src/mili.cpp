#include "material/mili.hpp"

#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "mesh/mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <sstream>

namespace sig {

namespace {

// Codes of the MILI arrays `law` and `plane`.
constexpr std::int64_t law_hooke = 1;
constexpr std::int64_t plane_strain_code = 1;
constexpr std::int64_t plane_stress_code = 2;

std::string joined(const std::vector<int>& numbers) {
  std::ostringstream out;
  for (std::size_t i = 0; i < numbers.size(); ++i)
    out << (i ? " " : "") << numbers[i];
  return out.str();
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

SubdomainMaterial material_from_card(const Card& card) {
  card.choice("law", {"hooke"}, "hooke");
  SubdomainMaterial material;
  material.hooke = hooke_from_card(card);
  material.thickness = card.real("thickness", 1.0);
  if (!(material.thickness > 0.0)) card.fail("thickness", "thickness must be > 0");
  material.density = card.real("rho", 0.0);
  if (!(material.density >= 0.0)) card.fail("rho", "density must be >= 0");
  return material;
}

MaterialTable material_table_from_cards(const Datafile& datafile, const Mesh& mesh) {
  const std::vector<int> present = mesh.subdomains();
  const std::vector<const Card*> cards = datafile.all("MATERIAL");
  if (cards.empty())
    throw InputError(datafile.path, 0, "",
                     "no MATERIAL card (sub-domains of the mesh: " + joined(present) + ")");

  std::map<int, const Card*> assigned_by;
  MaterialTable table;
  for (const Card* card : cards) {
    const SubdomainMaterial law = material_from_card(*card);
    std::vector<int> targets = present;
    if (card->has("region")) {
      targets.clear();
      for (long region : card->integers("region")) {
        if (!std::binary_search(present.begin(), present.end(), static_cast<int>(region))) {
          std::ostringstream what;
          what << "sub-domain " << region
               << " is not in the mesh; sub-domains present: " << joined(present);
          card->fail("region", what.str());
        }
        targets.push_back(static_cast<int>(region));
      }
    }
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
  return table;
}

void write_mili(const std::filesystem::path& path, const MaterialTable& table,
                const std::string& title) {
  std::vector<std::int64_t> subdomain, law, plane;
  std::vector<double> young, poisson, thickness, density;
  for (const SubdomainMaterial& m : table.entries) {
    subdomain.push_back(m.subdomain);
    law.push_back(law_hooke);
    plane.push_back(m.hooke.plane == PlaneMode::strain ? plane_strain_code : plane_stress_code);
    young.push_back(m.hooke.E);
    poisson.push_back(m.hooke.nu);
    thickness.push_back(m.thickness);
    density.push_back(m.density);
  }
  Ds ds("MILI", title, "sig-material");
  ds.put("subdomain", subdomain);
  ds.put("law", law);
  ds.put("young", young);
  ds.put("poisson", poisson);
  ds.put("plane", plane);
  ds.put("thickness", thickness);
  ds.put("density", density);
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
  SIG_VERIFY(law.size() == n && plane.size() == n && young.size() == n && poisson.size() == n &&
                 thickness.size() == n && density.size() == n,
             path.string() << ": MILI arrays have different lengths");
  MaterialTable table;
  for (std::size_t i = 0; i < n; ++i) {
    SIG_VERIFY(law[i] == law_hooke,
               path.string() << ": array 'law' row " << i + 1 << ": unknown law code " << law[i]);
    SIG_VERIFY(plane[i] == plane_strain_code || plane[i] == plane_stress_code,
               path.string() << ": array 'plane' row " << i + 1 << ": unknown code " << plane[i]);
    SIG_VERIFY(i == 0 || subdomain[i] > subdomain[i - 1],
               path.string() << ": array 'subdomain' is not strictly increasing at row " << i + 1);
    SubdomainMaterial m;
    m.subdomain = static_cast<int>(subdomain[i]);
    m.hooke.E = young[i];
    m.hooke.nu = poisson[i];
    m.hooke.plane = plane[i] == plane_strain_code ? PlaneMode::strain : PlaneMode::stress;
    m.thickness = thickness[i];
    m.density = density[i];
    table.entries.push_back(m);
  }
  return table;
}

} // namespace sig
