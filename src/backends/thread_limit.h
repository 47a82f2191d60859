// ThreadLimit: while it lives, at most `threads` threads run the process's parallel work (0: as
// many as there are cores). It covers whatever runs on oneTBB: loading (mesh ordering), BVH
// builds, Embree's among them (Debian's Embree schedules its tasks on oneTBB), the light-path
// pilot, the tiles. A caller that takes a thread count holds one around all of its work, so that
// a render told to use one core (a cluster task given one CPU, say) does not build on all of them.
#pragma once

#include <tbb/global_control.h>

#include <cstddef>
#include <optional>

namespace candela {

class ThreadLimit {
 public:
  explicit ThreadLimit(int threads) {
    if (threads > 0) limit_.emplace(tbb::global_control::max_allowed_parallelism, size_t(threads));
  }

 private:
  std::optional<tbb::global_control> limit_;
};

}  // namespace candela
