#pragma once
#include <cstdint>

// Bumped whenever a change to any SDK type could break a compiled plugin
// (class layout, virtual table, inline function semantics). The host refuses a
// plugin whose ABI version differs before touching any C++ type it exports.
#define DARKROOM_ABI_VERSION 2u

// Human-facing SDK release; informative only, compatibility is the ABI version.
#define DARKROOM_SDK_VERSION "0.2.0"
