// A session without MPI: one process holds everything.
#include "ranks.h"

namespace darkroom::insitu {

std::unique_ptr<ProcessGroup> aloneRanks() { return std::make_unique<SingleProcess>(); }

}  // namespace darkroom::insitu
