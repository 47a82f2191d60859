// Numeric constants shared by host and device code.
#pragma once

namespace candela {

constexpr float kPi = 3.14159265358979323846f;
constexpr double kPiDouble = 3.14159265358979323846;  // for the host's double arithmetic
constexpr float kInvPi = 0.31830988618379067154f;
constexpr float kInv4Pi = 0.07957747154594766788f;
constexpr float kInfinity = 3.402823466e+38f;  // FLT_MAX: usable as a ray's open tMax
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

}  // namespace candela
