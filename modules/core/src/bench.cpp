#include "core/bench.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <string>

namespace sig {

BenchArgs parse_bench_args(int argc, char** argv, const StageHelp& help) {
  handle_help_and_version(argc, argv, help);
  int repeat = 3;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--repeat") {
      SIG_VERIFY(i + 1 < argc, "--repeat needs a count");
      repeat = std::stoi(argv[++i]);
      SIG_VERIFY(repeat >= 1, "--repeat must be >= 1, not " << repeat);
    } else {
      rest.push_back(argv[i]);
    }
  }
  BenchArgs args{parse_stage_args(static_cast<int>(rest.size()), rest.data(), help)};
  args.repeat = repeat;
  return args;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace sig
