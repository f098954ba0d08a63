#include <darkroom/mpi/mpi_process_group.h>
// (header-only; this file keeps the class's vtable in the library)
