#include "entry_scheduler.h"

namespace darkroom::cli {

EntryScheduler::~EntryScheduler() = default;

std::optional<std::size_t> SerialEntryScheduler::next() {
    if (failed_ || next_ >= count_) return std::nullopt;
    return next_++;
}

std::vector<std::string> SerialEntryScheduler::gather(const std::string& mine, bool failedHere, bool& anyFailed) {
    anyFailed = failedHere || failed_;
    return {mine};
}

}  // namespace darkroom::cli
