#pragma once
// A list of records (an iteration history, a march's steps) goes to a DS as one array per field:
// the readers (sig-dump, postproc/sigreport) see columns, the stages keep structs.
#include "core/ds.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace sig {

/// Array `name`: `field` (a data member or a function of a record) of each record, in order;
/// Int64 for an integral or bool field, Float64 otherwise.
template <class Record, class Field>
void put_column(Ds& ds, const std::string& name, const std::vector<Record>& records, Field field) {
  using Value = std::remove_cvref_t<std::invoke_result_t<Field, const Record&>>;
  using Stored = std::conditional_t<std::is_integral_v<Value>, std::int64_t, double>;
  std::vector<Stored> column;
  column.reserve(records.size());
  for (const Record& r : records)
    column.push_back(static_cast<Stored>(std::invoke(field, r)));
  ds.put(name, column);
}

} // namespace sig
