// tiershade glue: rows of an image on worker threads, each with FTZ/DAZ set as llvmpipe
// computes (ts_math_init is per thread), rows interleaved so the load is even.
#pragma once
#include <algorithm>
#include <thread>
#include <vector>

#include "math/ts_math.h"

// fn(y) for y in [0, h) on `threads` workers (0 = all cores).
template <class Fn>
void scene_parallel_rows(int h, int threads, Fn fn) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::min(threads, std::max(1, h));
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([=] {
      ts_math_init();
      for (int y = t; y < h; y += threads) fn(y);
    });
  for (auto &th : pool) th.join();
}
