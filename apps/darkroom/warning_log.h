#pragma once
// The warnings of one run, each said once. A reader warns about its
// database's data.csv at every entry of `run --foreach`, the same words each
// time: the first is printed when it comes, the count at the end of the run.
#include <darkroom/diagnostics.h>

#include <cstddef>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace darkroom::cli {

class WarningLog {
public:
    // Whether the warning is met for the first time (to print now); a
    // repeat is only counted. Nodes of one depth run concurrently, so
    // calls may come from several threads.
    bool firstTime(const Diagnostic& warning);
    // One note per warning met more than once, with its count.
    void reportRepeats() const;

private:
    mutable std::mutex mutex_;
    std::map<std::string, std::size_t> counts_;
    std::vector<std::string> order_;  // as first met, so the notes come in that order
};

}  // namespace darkroom::cli
