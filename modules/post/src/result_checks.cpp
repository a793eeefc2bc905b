#include "post/result_checks.hpp"

#include "contact/contact_status.hpp"
#include "core/error.hpp"
#include "core/ranges.hpp"

#include <cmath>
#include <string>

namespace sig {

namespace {

std::int64_t integer_in(const Ds& ds, const std::string& name, std::int64_t low,
                        std::int64_t high) {
  const std::int64_t value = ds.integer(name);
  SIG_VERIFY(value >= low && value <= high, ds.source << ": array '" << name << "': " << value
                                                      << " is not in " << low << ".." << high);
  return value;
}

void codes_in(const Ds& ds, const std::string& name, std::int64_t low, std::int64_t high) {
  const std::vector<std::int64_t> codes = ds.ints(name);
  for (std::size_t i = 0; i < codes.size(); ++i)
    SIG_VERIFY(codes[i] >= low && codes[i] <= high,
               ds.source << ": array '" << name << "', row " << i + 1 << ": " << codes[i]
                         << " is not in " << low << ".." << high);
}

// Every displacement of a converged result within its bound of the mesh's size (core/ranges.hpp):
// an edited u = 1e300 was refused only by the VTK writer, naming a field of the .vtu, not the
// array. The last iterate of a solve that did not converge may have drifted any distance (a rigid
// motion held by nothing: its Nv says so), and is drawn as it is.
void displacements_in_range(const Ds& ds, const Mesh& mesh) {
  if (ds.integer("converged") != 1) return;
  const ValueRange range = displacement_range(diameter(mesh));
  const std::vector<double> u = ds.reals("u");
  for (std::size_t i = 0; i < u.size(); ++i)
    verify_in_range(u[i], range, ds.source, "u", i + 1);
}

std::size_t length(const Ds& ds, const std::string& name) {
  const std::vector<std::int64_t>& shape = ds.shape(name);
  return shape.empty() ? 0 : static_cast<std::size_t>(shape[0]);
}

} // namespace

void verify_solution_ds(const Ds& b, const Mesh& mesh) {
  const std::size_t dofs = static_cast<std::size_t>(mesh.dim) * mesh.num_nodes();
  integer_in(b, "converged", 0, 1);
  integer_in(b, "iterations", 0, 1000000000);
  SIG_VERIFY(b.reals("u").size() == dofs, b.source << ": array 'u' holds " << b.reals("u").size()
                                                   << " values, the mesh has " << dofs << " dofs");
  displacements_in_range(b, mesh);
  const std::int64_t m =
      b.has("multiplier") ? static_cast<std::int64_t>(length(b, "multiplier")) : 0;
  // ALM's multipliers: d per contact node at most (a normal one and d - 1 tangential).
  integer_in(b, "dofs", static_cast<std::int64_t>(dofs),
             static_cast<std::int64_t>(dofs) + mesh.dim * m);
  if (m > 0) {
    for (const char* name : {"tangential_multiplier", "status", "normal_status", "friction_status"})
      SIG_VERIFY(!b.has(name) || length(b, name) == static_cast<std::size_t>(m),
                 b.source << ": array '" << name << "' holds " << length(b, name) << " values for "
                          << m << " contact elements");
    if (b.has("status")) codes_in(b, "status", 0, 1);
    for (const std::int64_t code :
         b.has("normal_status") ? b.ints("normal_status") : std::vector<std::int64_t>{})
      try {
        normal_status_of_code(static_cast<long>(code));
      } catch (const Error& e) {
        SIG_VERIFY(false, b.source << ": array 'normal_status': " << e.what());
      }
    for (const std::int64_t code :
         b.has("friction_status") ? b.ints("friction_status") : std::vector<std::int64_t>{})
      try {
        friction_status_of_code(static_cast<long>(code));
      } catch (const Error& e) {
        SIG_VERIFY(false, b.source << ": array 'friction_status': " << e.what());
      }
  }
  if (b.has("start_iterations")) integer_in(b, "start_iterations", 0, 1000000000);
  if (b.has("start_fraction")) {
    const double fraction = b.scalar("start_fraction");
    SIG_VERIFY(fraction >= 0 && fraction <= 1,
               b.source << ": array 'start_fraction': " << fraction << " is not in [0, 1]");
  }
  if (b.has("history_active")) {
    const std::size_t iterations = length(b, "history_active");
    for (const char* name : {"history_entered", "history_left", "history_stick", "history_slip",
                             "history_residual", "history_increment", "history_step_norm"})
      SIG_VERIFY(!b.has(name) || length(b, name) == iterations,
                 b.source << ": array '" << name << "' holds " << length(b, name)
                          << " iterations, history_active " << iterations);
    for (const char* name :
         {"history_active", "history_entered", "history_left", "history_stick", "history_slip"})
      if (b.has(name)) codes_in(b, name, 0, m);
    if (b.has("history_wall")) {
      const std::vector<std::int64_t>& shape = b.shape("history_wall");
      SIG_VERIFY(shape.size() == 2 && shape[0] == static_cast<std::int64_t>(iterations) &&
                     shape[1] == m,
                 b.source << ": array 'history_wall' is not " << iterations << " iterations x " << m
                          << " contact nodes");
      codes_in(b, "history_wall", 0, 1);
    }
  }
}

void verify_history_ds(const Ds& hist, const Mesh& mesh) {
  const std::string& file = hist.source;
  const double k = hist.scalar("k"), final_time = hist.scalar("T");
  verify_in_range(k, "TIME", "k", file, "k", 1);
  verify_in_range(final_time, "TIME", "T", file, "T", 1);
  const std::int64_t steps = integer_in(hist, "steps", 1, 1000000000);
  SIG_VERIFY(std::abs(static_cast<double>(steps) * k - final_time) <= 1e-9 * final_time,
             file << ": array 'steps': " << steps << " steps of k = " << k
                  << " do not make T = " << final_time);
  verify_in_range(static_cast<double>(hist.integer("output_every")), "TIME", "output_every", file,
                  "output_every", 1);
  integer_in(hist, "converged", 0, 1);
  const std::int64_t ndof = hist.integer("ndof");
  SIG_VERIFY(ndof == mesh.dim * static_cast<std::int64_t>(mesh.num_nodes()),
             file << ": array 'ndof': " << ndof << ", the mesh has " << mesh.dim * mesh.num_nodes()
                  << " dofs");

  // Per step: one length, that of the steps done (all of them unless the march stopped).
  const std::size_t done = length(hist, "step");
  SIG_VERIFY(done >= 1 && done <= static_cast<std::size_t>(steps) + 1,
             file << ": array 'step' holds " << done << " steps, the march has " << steps + 1);
  SIG_VERIFY(length(hist, "time") == done,
             file << ": array 'time' holds " << length(hist, "time") << " steps, 'step' " << done);
  for (const char* name : {"kinetic", "elastic", "total", "external_work", "newton_iterations"})
    SIG_VERIFY(!hist.has(name) || length(hist, name) == done,
               file << ": array '" << name << "' holds " << length(hist, name) << " steps, 'step' "
                    << done);
  const std::vector<std::int64_t> step = hist.ints("step");
  for (std::size_t s = 0; s < done; ++s)
    SIG_VERIFY(step[s] == static_cast<std::int64_t>(s),
               file << ": array 'step', row " << s + 1 << ": " << step[s] << " is not " << s);

  // The kept states: increasing steps among those done, at their times.
  const std::vector<std::int64_t> output_step = hist.ints("output_step");
  const std::vector<double> output_time = hist.reals("output_time");
  const std::vector<double> time = hist.reals("time");
  const std::size_t outputs = output_step.size();
  SIG_VERIFY(outputs >= 1 && output_time.size() == outputs,
             file << ": arrays 'output_step' and 'output_time' hold " << outputs << " and "
                  << output_time.size() << " states");
  for (std::size_t i = 0; i < outputs; ++i) {
    SIG_VERIFY(output_step[i] >= 0 && static_cast<std::size_t>(output_step[i]) < done &&
                   (i == 0 || output_step[i] > output_step[i - 1]),
               file << ": array 'output_step', row " << i + 1 << ": step " << output_step[i]
                    << " is not after the previous one among the " << done << " steps done");
    const double t = time[static_cast<std::size_t>(output_step[i])];
    SIG_VERIFY(std::abs(output_time[i] - t) <= 1e-9 * std::max(1.0, std::abs(t)),
               file << ": array 'output_time', row " << i + 1 << ": " << output_time[i]
                    << " is not the time " << t << " of step " << output_step[i]);
  }
  for (const char* name : {"u", "v"}) {
    const std::vector<std::int64_t>& shape = hist.shape(name);
    SIG_VERIFY(
        shape.size() == 2 && static_cast<std::size_t>(shape[0]) == outputs && shape[1] == ndof,
        file << ": array '" << name << "' is not " << outputs << " states x " << ndof << " dofs");
  }
  displacements_in_range(hist, mesh);
}

} // namespace sig
