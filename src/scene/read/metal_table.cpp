// The named metals; see metal_table.h.
//
// The values are the RGB indices Mitsuba 3 (scalar_rgb) derives from its spectral tables for the
// same names (mi.load_dict({"type": "conductor", "material": name}) and mi.traverse), so that a
// reference rendered with Mitsuba's named metal is the same metal.
#include "scene/read/metal_table.h"

namespace candela {

const std::vector<NamedMetal>& namedMetals() {
  static const std::vector<NamedMetal> metals = {
      {"Ag", {0.155276f, 0.116728f, 0.138388f}, {4.82835f, 3.12222f, 2.1469f}},
      {"Al", {1.6575f, 0.880405f, 0.521244f}, {9.22381f, 6.2695f, 4.837f}},
      {"Au", {0.143036f, 0.375307f, 1.44205f}, {3.983f, 2.38556f, 1.60336f}},
      {"Cr", {4.36967f, 2.91651f, 1.6549f}, {5.20655f, 4.23131f, 3.7547f}},
      {"Cu", {0.201005f, 0.92375f, 1.10222f}, {3.91326f, 2.45305f, 2.14209f}},
  };
  return metals;
}

}  // namespace candela
