// tiershade base: the one thread pool: rows of an image on worker threads, each with FTZ/DAZ
// set as llvmpipe computes (ts_math_init is per thread), rows interleaved so the load is even
// (worker t takes rows t, t + n, t + 2n...: the same rows on every run).
#pragma once
#include <algorithm>
#include <thread>
#include <vector>

#include "math/ts_math.h"

// The number of workers parallel_rows starts for h rows and `threads` (0 = all cores).
inline int parallel_workers(int h, int threads) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::min(threads, std::max(1, h));
}

// fn(t, y) for y in [0, h): worker t in [0, parallel_workers(h, threads)) takes the rows y = t mod n.
template <class Fn>
void parallel_rows_by_worker(int h, int threads, Fn fn) {
  const int n = parallel_workers(h, threads);
  std::vector<std::thread> pool;
  for (int t = 0; t < n; ++t)
    pool.emplace_back([=] {
      ts_math_init();
      for (int y = t; y < h; y += n) fn(t, y);
    });
  for (auto &th : pool) th.join();
}

// fn(y) for y in [0, h) on `threads` workers (0 = all cores).
template <class Fn>
void parallel_rows(int h, int threads, Fn fn) {
  parallel_rows_by_worker(h, threads, [&fn](int, int y) { fn(y); });
}
