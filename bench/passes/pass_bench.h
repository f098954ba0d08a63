#pragma once
// Shared harness for pass benchmarks: a synthetic G-buffer, the build's
// plugins, and counters that put each pass next to a memcpy of the bytes it
// must read and write, measured in the same process.
#include <benchmark/benchmark.h>
#include <darkroom/buffer.h>
#include <darkroom/value.h>

#include <map>
#include <string>
#include <vector>

namespace darkroom::bench {

// size x size G-buffer of a bumpy terrain seen from above: Z (with ~10 %
// background), N.x/N.y/N.z, a scalar "value", linear R, G, B, A, objectId.
BufferPtr syntheticGBuffer(int size);

// Runs filter `type` on `inputs` (image ports get syntheticGBuffer(size) when
// not given) for every benchmark iteration, and sets counters:
//   MP/s        megapixels per second
//   vs_memcpy   median pass time / median time of a memcpy of (input channels
//               read + output channels written) bytes, the memcpy run before
//               every iteration so that both see the same machine load
//   median_ms   median pass time
//   cpu_ms      median CPU time of the process (all threads) per pass
// `channelsRead` is how many float channels of the input the pass reads.
void runPass(benchmark::State& state, const std::string& type, int size, int channelsRead,
             const std::map<std::string, Value>& parameters = {});

// Like runPass, but with the images given per port (several for a `multiple`
// port such as Compositing's). `channelsRead` counts the float channels read
// over all inputs together.
void runPassWithImages(benchmark::State& state, const std::string& type, int size, int channelsRead,
                       const std::map<std::string, std::vector<BufferPtr>>& images,
                       const std::map<std::string, Value>& parameters = {});

}  // namespace darkroom::bench
