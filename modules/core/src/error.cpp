#include "core/error.hpp"

#include <utility>

namespace sig {

namespace {
// "file:line: field 'name': what", dropping the parts that do not apply so that a missing card
// reads "deck.dat: missing card MESH" and a bad line "deck.dat:7: unknown card FOO".
std::string input_message(const std::string& file, int line, const std::string& field,
                          const std::string& what) {
  std::string message = file;
  if (line > 0) message.append(":").append(std::to_string(line));
  message.append(": ");
  if (!field.empty()) message.append("field '").append(field).append("': ");
  return message.append(what);
}
} // namespace

InputError::InputError(std::string file, int line, std::string field, const std::string& what)
    : Error(input_message(file, line, field, what)), file_(std::move(file)), line_(line),
      field_(std::move(field)) {}

} // namespace sig
