#include "stages/convexification_step.hpp"

#include "contact/contact_law.hpp"
#include "solver/contact_bulk.hpp"
#include "solver/convexification.hpp"
#include "stages/history_io.hpp"

#include <algorithm>
#include <memory>
#include <numeric>

namespace sig {

double ConvexificationRecords::total() const {
  return std::accumulate(outer.begin(), outer.end(), 0.0);
}

double ConvexificationRecords::most() const {
  return outer.empty() ? 0.0 : *std::max_element(outer.begin(), outer.end());
}

StepSolver convexification_step(const VelocityScheme& scheme, const VelocityContact* contact,
                                const SolverCard& solver, ConvexificationRecords& records) {
  if (contact == nullptr || !needs_convexification(contact->setting.law)) return {};
  std::shared_ptr<const ContactMethod> method = make_contact_method(solver.parameters);
  const ContactNewtonOptions inner = newton_options(solver.parameters);
  const ConvexificationOptions options = solver.convexification;
  return [&scheme, contact, &records, method, inner,
          options](ContactBulk& bulk, const ContactSetting& setting, ContactIterate& iterate) {
    // mu(0) of the previous step's slip rate |w_t|: the bulk restarts from its velocity.
    ContactSetting start = setting;
    if (options.start == ConvexificationStart::given) {
      const Eigen::VectorXd rate = tangential_squares(bulk.slip(), start.size()).cwiseSqrt();
      for (int p = 0; p < start.size(); ++p)
        start.law[p].mu = friction_coefficient(start.law[p], rate[p]);
    }
    const int n = static_cast<int>(records.outer.size()); // this step: one record per step before
    const Eigen::VectorXd origin = scheme.normal_origin(n, *contact);
    ConvexificationMeasures measures;
    measures.displacement = [&origin](const ContactBulk& b) {
      const Eigen::VectorXd slip = b.slip();
      Eigen::VectorXd v(origin.size() + slip.size());
      v << b.penetration() + origin, slip;
      return v;
    };
    ConvexificationResult r = convexify(bulk, start, *method, inner, options, measures, iterate);
    records.outer.push_back(r.outer_iterations());
    records.outer_converged.push_back(r.converged ? 1 : 0);
    records.cycle.push_back(r.cycle);
    ContactNewtonResult result = std::move(r.last);
    result.converged = r.converged;
    result.failure = r.failure;
    result.history = std::move(r.inner_history);
    return result;
  };
}

void add_convexification_columns(const ConvexificationRecords& records, HistoryInfo& info) {
  if (records.outer.size() <= 1) return;
  info.step_columns.push_back({"outer_iterations", records.outer});
  info.step_columns.push_back({"outer_converged", records.outer_converged});
  info.step_columns.push_back({"status_cycle", records.cycle});
}

} // namespace sig
