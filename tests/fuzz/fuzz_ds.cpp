// DS container reader: header, arrays, CRCs, trailer, then every array through its accessor and
// the provenance a DS records.
#include "core/ds.hpp"
#include "core/provenance.hpp"
#include "fuzz_target.hpp"

void sig::fuzz::read_input(const std::string& bytes) {
  const Ds ds = parse_ds("fuzz.ds", bytes);
  for (const DsArray& array : ds.arrays()) {
    ds.shape(array.name);
    try {
      switch (array.type) {
      case DsType::Float64:
        ds.reals_any(array.name);
        ds.reals(array.name);
        break;
      case DsType::Int64:
        ds.ints(array.name);
        break;
      case DsType::Text:
        if (array.name == "provenance") parse_provenance(ds.text(array.name), ds.source);
        ds.text(array.name);
      }
    } catch (const Error&) {
      // NaN in reals, a bad provenance line: refused, keep reading the others
    }
  }
}
