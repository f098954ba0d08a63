// The HDF5 library set-up shared by the .h5 reader and writer.
#include "h5_handle.h"

#include <H5PLpublic.h>
#include <fmt/format.h>

#include <atomic>
#include <mutex>
#include <unistd.h>

namespace darkroom::h5 {

void prepareLibrary() {
    // The error stack's automatic printing is per thread: switch it off on
    // each thread that calls in; a failure is reported by our exceptions.
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    // A file may name any filter; HDF5 would then search HDF5_PLUGIN_PATH
    // for a library to dlopen. Only the built-in filters (deflate, shuffle,
    // fletcher32, szip, ...) are used; once for the process.
    static std::once_flag plugins;
    std::call_once(plugins, [] { H5PLset_loading_state(0); });
}

std::string uniqueMemoryName(const char* purpose) {
    // The core driver keeps such files in memory only; HDF5 still tells open
    // files apart by name, so concurrent readers and writers need their own.
    static std::atomic<unsigned long long> counter{0};
    return fmt::format("darkroom-{}-{}-{}.h5", purpose, ::getpid(), counter.fetch_add(1));
}

}  // namespace darkroom::h5
