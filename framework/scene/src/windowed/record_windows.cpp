#include "record_windows.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>

namespace darkroom::windowed {
namespace {

// Records per parallel task: big enough to amortise a task, small enough to
// share a window between the cores.
constexpr std::size_t kGrain = std::size_t(1) << 14;

}  // namespace

bool readRecords(const FileRangeReader& file, std::uint64_t offset, std::size_t count, std::size_t recordSize,
                 std::size_t windowBytes, std::vector<char>& buffer, const std::function<bool(const Span&)>& decode) {
    const std::size_t perWindow = std::max<std::size_t>(1, windowBytes / recordSize);
    for (std::size_t first = 0; first < count; first += perWindow) {
        const std::size_t n = std::min(perWindow, count - first);
        if (buffer.size() < n * recordSize) buffer.resize(n * recordSize);
        if (!file.read(offset + first * recordSize, n * recordSize, buffer.data())) return false;
        std::atomic<bool> ok{true};
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
            if (!decode({buffer.data(), first, r.begin(), r.end()})) ok.store(false, std::memory_order_relaxed);
        });
        if (!ok.load()) return false;
    }
    return true;
}

}  // namespace darkroom::windowed
