#include "warning_log.h"

#include <cstdio>

namespace darkroom::cli {

bool WarningLog::firstTime(const Diagnostic& warning) {
    const std::string text = warning.str();
    std::lock_guard<std::mutex> lock(mutex_);
    if (++counts_[text] > 1) return false;
    order_.push_back(text);
    return true;
}

void WarningLog::reportRepeats() const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& text : order_)
        if (const std::size_t n = counts_.at(text); n > 1)
            std::fprintf(stderr, "darkroom: note: given %zu times in this run, shown once above: %s\n", n, text.c_str());
}

}  // namespace darkroom::cli
