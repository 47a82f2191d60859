// The CPU's sample tables (core/sample_table.h): a packet's random numbers computed 8 lanes at a
// time with AVX2, where the CPU has it.
#pragma once

#include <cstdint>

#include "core/sample_table.h"

namespace candela {

// The fill for this CPU: the AVX2 one, or null where the CPU has no AVX2 (there SampleStreams
// compute their own numbers: 32-bit multiplies emulated in SSE2 cost more than they save).
SampleTable::Fill sampleTableFill();

// The AVX2 fill (backends/cpu/sample_table_avx2.cpp); only where the CPU has AVX2.
void fillSampleTableAvx2(SampleTable* table, uint32_t entry, bool twoD);

}  // namespace candela
