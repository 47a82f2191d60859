#include "backends/cpu/sample_table_fill.h"

namespace candela {

SampleTable::Fill sampleTableFill() {
#if defined(__x86_64__)
  static const SampleTable::Fill fill =
      __builtin_cpu_supports("avx2") ? fillSampleTableAvx2 : nullptr;
  return fill;
#else
  return nullptr;
#endif
}

}  // namespace candela
