#pragma once
#include <cstdint>

// Bumped whenever a change to any SDK type could break a compiled plugin
// (class layout, virtual table, inline function semantics). The host refuses a
// plugin whose ABI version differs before touching any C++ type it exports.
// This line is the only place the number is written: CMake reads it for the
// config package, and CI compares the SDK library's ABI with the baseline
// recorded for this number (sdk/abi/, tests/sdk/check_abi.sh).
#define DARKROOM_ABI_VERSION 4u

// Human-facing SDK release; informative only, compatibility is the ABI version.
#define DARKROOM_SDK_VERSION "0.4.0"
