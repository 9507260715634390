#pragma once
// Wall time of a piece of work over several repetitions, for the benchmark drivers: (minimum, median).
#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

namespace servodrift::bench
{
  template <typename F>
  std::pair<double, double> time_it(int repetitions, F &&f)
  {
    std::vector<double> t;
    for (int k = 0; k < repetitions; ++k)
      {
        const auto start = std::chrono::steady_clock::now();
        f();
        t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      }
    std::sort(t.begin(), t.end());
    return {t.front(), t[t.size() / 2]};
  }
} // namespace servodrift::bench
