#include "core/ds.hpp"

#include "core/error.hpp"
#include "core/finite.hpp"
#include "core/stage.hpp"

#include <algorithm>
#include <cstring>

namespace sig {

namespace {
std::size_t value_size(DsType type) {
  return type == DsType::Text ? 1 : 8;
}

const char* type_name(DsType type) {
  switch (type) {
  case DsType::Int64:
    return "Int64";
  case DsType::Float64:
    return "Float64";
  case DsType::Text:
    return "Text";
  }
  return "unknown";
}

std::vector<std::int64_t> checked_shape(const std::string& name, std::vector<std::int64_t> shape,
                                        std::size_t count) {
  if (shape.empty()) return {static_cast<std::int64_t>(count)};
  std::int64_t product = 1;
  for (const auto n : shape) {
    SIG_VERIFY(n >= 0, "DS array '" << name << "': negative extent " << n << " in its shape");
    SIG_VERIFY(!__builtin_mul_overflow(product, n, &product),
               "DS array '" << name << "': shape overflows");
  }
  SIG_VERIFY(static_cast<std::size_t>(product) == count,
             "DS array '" << name << "': shape holds " << product << " values, data has " << count);
  return shape;
}

template <class T>
DsArray make_array(const std::string& name, DsType type, std::span<const T> values,
                   std::vector<std::int64_t> shape) {
  SIG_VERIFY(is_valid_array_name(name),
             "DS array name '" << name << "' must have 1 to " << kMaxArrayName << " characters");
  DsArray array;
  array.name = name;
  array.type = type;
  array.shape = checked_shape(name, std::move(shape), values.size());
  array.bytes.resize(values.size_bytes());
  if (!values.empty()) std::memcpy(array.bytes.data(), values.data(), values.size_bytes());
  return array;
}

void replace_or_append(std::vector<DsArray>& arrays, DsArray array) {
  auto same = std::find_if(arrays.begin(), arrays.end(),
                           [&](const DsArray& a) { return a.name == array.name; });
  if (same != arrays.end())
    *same = std::move(array);
  else
    arrays.push_back(std::move(array));
}

template <class T> std::vector<T> values_of(const DsArray& array) {
  std::vector<T> values(array.bytes.size() / sizeof(T));
  if (!values.empty()) std::memcpy(values.data(), array.bytes.data(), values.size() * sizeof(T));
  return values;
}
} // namespace

bool is_valid_array_name(const std::string& name) {
  return !name.empty() && name.size() <= kMaxArrayName && name.find('\0') == std::string::npos;
}

std::size_t DsArray::count() const {
  return bytes.size() / value_size(type);
}

Ds::Ds(std::string kind, std::string title, std::string creator) {
  header.kind = std::move(kind);
  header.title = std::move(title);
  header.creator = std::move(creator);
  header.date = ds_date();
}

void Ds::put(const std::string& name, std::span<const double> values,
             std::vector<std::int64_t> shape, Finite finite) {
  DsArray array = make_array(name, DsType::Float64, values, std::move(shape));
  array.finite = finite;
  replace_or_append(arrays_, std::move(array));
}

void Ds::put(const std::string& name, std::span<const std::int64_t> values,
             std::vector<std::int64_t> shape) {
  replace_or_append(arrays_, make_array(name, DsType::Int64, values, std::move(shape)));
}

void Ds::put_text(const std::string& name, const std::string& text) {
  replace_or_append(
      arrays_, make_array(name, DsType::Text, std::span<const char>(text.data(), text.size()), {}));
}

void Ds::put_scalar(const std::string& name, double value) {
  put(name, std::span<const double>(&value, 1));
}

void Ds::put_int(const std::string& name, std::int64_t value) {
  put(name, std::span<const std::int64_t>(&value, 1));
}

void Ds::put(DsArray array) {
  SIG_VERIFY(is_valid_array_name(array.name), "DS array name '" << array.name << "' must have 1 to "
                                                                << kMaxArrayName << " characters");
  SIG_VERIFY(
      array.type == DsType::Int64 || array.type == DsType::Float64 || array.type == DsType::Text,
      "DS array '" << array.name << "': unknown type " << static_cast<std::uint32_t>(array.type));
  const std::size_t size = value_size(array.type);
  SIG_VERIFY(array.bytes.size() % size == 0, "DS array '"
                                                 << array.name << "': " << array.bytes.size()
                                                 << " bytes is not a whole number of values");
  array.shape = checked_shape(array.name, std::move(array.shape), array.bytes.size() / size);
  replace_or_append(arrays_, std::move(array));
}

bool Ds::has(const std::string& name) const {
  return std::any_of(arrays_.begin(), arrays_.end(),
                     [&](const DsArray& a) { return a.name == name; });
}

const DsArray& Ds::find(const std::string& name, DsType type) const {
  const std::string where = source.empty() ? "DS " + header.kind : source;
  auto it = std::find_if(arrays_.begin(), arrays_.end(),
                         [&](const DsArray& a) { return a.name == name; });
  SIG_VERIFY(it != arrays_.end(), where << ": array '" << name << "': missing");
  SIG_VERIFY(it->type == type, where << ": array '" << name << "': holds " << type_name(it->type)
                                     << ", expected " << type_name(type));
  return *it;
}

std::vector<double> Ds::reals(const std::string& name) const {
  std::vector<double> values = reals_any(name);
  const std::string bad = first_non_finite(values);
  SIG_VERIFY(bad.empty(), (source.empty() ? "DS " + header.kind : source)
                              << ": array '" << name << "': " << bad
                              << " (its CRC is valid: the file was written or edited so)");
  return values;
}

std::vector<double> Ds::reals_any(const std::string& name) const {
  return values_of<double>(find(name, DsType::Float64));
}

std::vector<std::int64_t> Ds::ints(const std::string& name) const {
  return values_of<std::int64_t>(find(name, DsType::Int64));
}

std::string Ds::text(const std::string& name) const {
  const DsArray& array = find(name, DsType::Text);
  return std::string(array.bytes.begin(), array.bytes.end());
}

double Ds::scalar(const std::string& name) const {
  const auto values = reals(name);
  SIG_VERIFY(values.size() == 1, (source.empty() ? "DS " + header.kind : source)
                                     << ": array '" << name << "': expected one value, found "
                                     << values.size());
  return values[0];
}

std::int64_t Ds::integer(const std::string& name) const {
  const auto values = ints(name);
  SIG_VERIFY(values.size() == 1, (source.empty() ? "DS " + header.kind : source)
                                     << ": array '" << name << "': expected one value, found "
                                     << values.size());
  return values[0];
}

const std::vector<std::int64_t>& Ds::shape(const std::string& name) const {
  auto it = std::find_if(arrays_.begin(), arrays_.end(),
                         [&](const DsArray& a) { return a.name == name; });
  SIG_VERIFY(it != arrays_.end(), (source.empty() ? "DS " + header.kind : source)
                                      << ": array '" << name << "': missing");
  return it->shape;
}

} // namespace sig
