// Built without MPI: a session cannot be shared over ranks.
#include "ranks.h"

#include <darkroom/error.h>

namespace darkroom::insitu {

std::unique_ptr<ProcessGroup> mpiRanks(int) {
    throw Error("in situ: this Darkroom was built without MPI (-DDARKROOM_WITH_MPI=OFF); a session runs in one "
                "process only");
}

}  // namespace darkroom::insitu
