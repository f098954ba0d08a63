// Debian 12's Highway (libhwy 1.0.3) measures its timer's resolution in a
// static initializer of nanobenchmark.cc, a spin of about 6 ms on the 2-core
// machine that every process linking libhwy pays at start — a third of
// `darkroom --help` (18 ms) — for a value only hwy::Measure (its
// micro-benchmark, which Darkroom never calls) reads. libhwy calls it through
// its PLT, so this definition, exported from the executable
// (--export-dynamic-symbol in CMakeLists.txt), is the one the initializer
// reaches. Nothing else changes: dispatch (hwy::SupportedTargets) is not
// touched. A later libhwy that measures lazily, or another symbol version,
// simply never calls this.
#include <hwy/nanobenchmark.h>

namespace hwy::platform {

uint64_t TimerResolution() { return 1; }  // the least a tick counter can resolve

}  // namespace hwy::platform
