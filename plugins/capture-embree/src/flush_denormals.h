#pragma once
// Embree recommends flush-to-zero and denormals-are-zero for speed. Worker
// threads belong to the host, so the previous mode is restored on scope exit.
#include <pmmintrin.h>
#include <xmmintrin.h>

namespace darkroom::embree {

class FlushDenormals {
public:
    FlushDenormals() : saved_(_mm_getcsr()) {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    }
    ~FlushDenormals() { _mm_setcsr(saved_); }
    FlushDenormals(const FlushDenormals&) = delete;
    FlushDenormals& operator=(const FlushDenormals&) = delete;

private:
    unsigned saved_;
};

}  // namespace darkroom::embree
