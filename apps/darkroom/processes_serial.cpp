// A runner built without MPI always runs as one process.
#include "processes.h"

namespace darkroom::cli {

ProcessScope::ProcessScope(int*, char***) {}
ProcessScope::~ProcessScope() = default;

const Processes& processes() {
    static const Processes alone;
    return alone;
}

int defaultThreads() { return 0; }

int failAllProcesses(int code) { return code; }

}  // namespace darkroom::cli

#include "capture_over_ranks.h"

namespace darkroom::cli {

int captureOverRanks(const GlobalOptions&, const CaptureSettings&) {
    reportError("this darkroom was built without MPI (-DDARKROOM_WITH_MPI=OFF); it cannot capture over ranks");
    return kBadInput;
}

}  // namespace darkroom::cli

#include "entry_scheduler.h"

namespace darkroom::cli {

std::unique_ptr<EntryScheduler> makeEntryScheduler() { return std::make_unique<SerialEntryScheduler>(); }

}  // namespace darkroom::cli
