#include "stages/augmentation_scale.hpp"

#include "core/datafile.hpp"
#include "core/log.hpp"
#include "solver/contact_method.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace sig {

std::optional<double> natural_contact_scale(const Eigen::SparseMatrix<double>& stiffness,
                                            const ContactElements& contact) {
  const int d = contact.dim;
  std::vector<double> scales;
  for (int p = 0; p < contact.size(); ++p) {
    const int first = d * contact.node[p];
    if (first + d > stiffness.rows() || !(contact.weight[p] > 0)) continue;
    double normal = 0;
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j)
        normal +=
            contact.normal[p][i] * stiffness.coeff(first + i, first + j) * contact.normal[p][j];
    if (normal > 0) scales.push_back(normal / contact.weight[p]);
  }
  if (scales.empty()) return std::nullopt;
  auto middle = scales.begin() + static_cast<std::ptrdiff_t>(scales.size() / 2);
  std::nth_element(scales.begin(), middle, scales.end());
  return *middle;
}

std::string augmentation_scale_hint(const Datafile& datafile, const std::string& method,
                                    const Eigen::SparseMatrix<double>& stiffness,
                                    const ContactElements& contact, bool lower_only) {
  const char* field = method == "alm" ? "r" : method == "pdas" ? "gamma" : "c";
  if (method != "alm" && method != "pdas" && method != "projection") return ""; // penalty: a model
  const std::optional<double> scale = natural_contact_scale(stiffness, contact);
  if (!scale) return "";
  const double natural = *scale;
  const Card* solver = datafile.find("SOLVER");
  const bool given = solver && solver->has(field);
  const double value = given ? solver->real(field) : ContactSolverParameters::card_default(field);
  const double augmentation = method == "projection" ? 1 / value : value;
  const double ratio = augmentation / natural;
  if (ratio >= 1e-4 && (lower_only || ratio <= 1e6)) return "";
  char words[512];
  std::snprintf(words, sizeof words,
                "SOLVER %s=%.3g%s is %.1e times the contact nodes' natural scale (their normal "
                "stiffness over their weight, median %.3g, a pressure per length): the contact "
                "Newton is checked from 1e-2 to 1e4 times it and may fail this far off: try "
                "%s=%.3g, or a value in that range",
                field, value, given ? "" : " (the default)", ratio, natural, field,
                method == "projection" ? 1 / natural : natural);
  const std::string place =
      solver ? solver->file + ":" + std::to_string(solver->line) + ": " : datafile.path + ": ";
  return place + words;
}

void hint_augmentation_scale(const Datafile& datafile, const std::string& method,
                             const Eigen::SparseMatrix<double>& stiffness,
                             const ContactElements& contact, bool lower_only) {
  if (const std::string words =
          augmentation_scale_hint(datafile, method, stiffness, contact, lower_only);
      !words.empty())
    log_warning(words);
}

} // namespace sig
