#pragma once
// The processes an in situ session spans, as the framework's ProcessGroup
// (darkroom/core/process_group.h) that the capture workflow talks to: this
// process alone, or the ranks of the simulation's MPI communicator
// (mpi_ranks.cpp, built with MPI).
#include <darkroom/core/process_group.h>

#include <memory>

namespace darkroom::insitu {

std::unique_ptr<ProcessGroup> aloneRanks();
// Over a duplicate of the simulation's communicator, freed with the group.
// Throws darkroom::Error when the library was built without MPI or the
// handle is not a communicator.
std::unique_ptr<ProcessGroup> mpiRanks(int fortranComm);

}  // namespace darkroom::insitu
