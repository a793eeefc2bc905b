#include "core/bench.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <charconv>
#include <string>

namespace sig {

BenchArgs parse_bench_args(int argc, char** argv, const StageHelp& help) {
  handle_help_and_version(argc, argv, help);
  int repeat = 3;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--repeat") {
      SIG_VERIFY(i + 1 < argc, "--repeat needs a count");
      const std::string text = argv[++i];
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), repeat);
      // "2x" or "abc" must not run a benchmark with a count the user did not write.
      SIG_VERIFY(error == std::errc{} && end == text.data() + text.size() && repeat >= 1,
                 "--repeat: '" << text << "' is not a positive whole number");
    } else {
      rest.push_back(argv[i]);
    }
  }
  BenchArgs args{parse_stage_args(static_cast<int>(rest.size()), rest.data(), help)};
  args.repeat = repeat;
  return args;
}

double median(std::vector<double> values) {
  SIG_VERIFY(!values.empty(), "median of no values");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace sig
