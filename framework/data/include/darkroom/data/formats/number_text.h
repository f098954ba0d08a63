#pragma once
// A value read from a mesh file, for an error message, as the file wrote it:
// converting 2.2e54 or NaN to long long to print it was undefined behaviour
// (found by the VTK legacy fuzz harness, tests/fuzz).
#include <cmath>
#include <sstream>
#include <string>

namespace darkroom::mesh {

inline std::string numberText(double v) {
    if (v == std::floor(v) && std::abs(v) < 9.0e15) return std::to_string(static_cast<long long>(v));
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace darkroom::mesh
